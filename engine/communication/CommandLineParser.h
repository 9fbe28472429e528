#pragma once
// Parses `mixengine slice` arguments exactly as CuraEngine 4.13 does (see `mixengine help`):
// settings apply to the last focus — global, then `-g` (mesh group), `-eN` (extruder train), the
// last `-l` model; `--next` starts a new mesh group; `mesh_rotation_matrix` in force when `-l` is
// read applies to that model. Throws InputError naming the argument at fault.
#include <string>
#include <vector>

#include "pipeline/SliceRequest.h"

namespace mixengine {

/// `args` are the words after `slice`. Extra words understood besides CuraEngine's:
///   --dump-layers DIR   (recorded in `dump_layers_dir`)
///   --preview FILE.png  (recorded in `preview_png`: a side view coloured by the mix, mixing/Preview.h)
struct ParsedSliceArgs {
    SliceRequest request;
    std::string dump_layers_dir;
    std::string preview_png;
};

ParsedSliceArgs parseSliceArguments(const std::vector<std::string>& args);

/// Splits "key=value"; throws InputError when there is no '=' or the key is empty.
std::pair<std::string, std::string> splitSettingArgument(const std::string& word);

}  // namespace mixengine
