#pragma once
// The profile files Cura 4.13 would register for one machine, read from resource roots laid out like
// /usr/share/cura/resources: variants/**.inst.cfg, quality/**.inst.cfg, intent/**.inst.cfg and
// materials/**.xml.fdm_material.
//
// Only what a selection for `definition_ids` can use is kept: instance containers whose
// `definition` is one of them (the machine, its quality_definition and "fdmprinter"), and every
// material file. Containers are sorted by id, so that where Cura's own choice depends on the order
// in which its registry happened to load files (a fallback "any material" / "any quality"), the
// result is at least deterministic. When two roots hold the same id, the earlier root wins.
// A file that cannot be parsed is skipped and reported in `problems` (Cura logs and skips it too).
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "settings/profiles/InstCfg.h"
#include "settings/profiles/MaterialProfile.h"

namespace mixengine {

struct ProfileResources {
    std::vector<InstCfgFile> variants;   ///< type = variant
    std::vector<InstCfgFile> qualities;  ///< type = quality
    std::vector<InstCfgFile> intents;    ///< type = intent
    std::vector<MaterialProfile> materials;
    std::vector<std::string> problems;  ///< "file: problem" for files that were skipped
};

/// Reads the resources under `roots` (each a folder with variants/, quality/, intent/, materials/;
/// missing sub-folders are fine).
ProfileResources loadProfileResources(const std::vector<std::filesystem::path>& roots,
                                      const std::set<std::string, std::less<>>& definition_ids);

/// The resource roots for a definition search path (settings/DefinitionSet.h defaultSearchPath):
/// each folder of the path and its parent that has a variants/, quality/, intent/ or materials/
/// sub-folder, in search order without repeats — e.g. /usr/share/cura/resources for its
/// definitions/ folder.
std::vector<std::filesystem::path> profileRoots(const std::vector<std::filesystem::path>& search_path);

}  // namespace mixengine
