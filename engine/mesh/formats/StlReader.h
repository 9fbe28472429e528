#pragma once
// STL input (binary and ASCII) into one triangle soup named after the file stem.
//
// Format detection (a binary file may begin with "solid"):
//   1. the size equals 84 + 50 * (count in the header)        -> binary;
//   2. otherwise the file starts with "solid" and is all text  -> ASCII (errors are ASCII errors);
//   3. otherwise                                               -> binary with a wrong counter.
// Binary: whole 50-byte records are read when the data is intact (counter too high or too low,
// trailing bytes: one warning each); a record cut short is an InputError. ASCII: several `solid`
// blocks are merged (warning). Both: non-finite vertex coordinates are an InputError, non-finite
// normals only a warning (normals are ignored). No triangles at all is an InputError.
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/formats/ModelReader.h"

namespace mixengine {

TriangleSoup readStl(const std::filesystem::path& file, std::vector<std::string>& warnings);

}  // namespace mixengine
