#pragma once
// Cura's material files (*.xml.fdm_material, the fdm-materials package), read as Cura 4.13's
// XmlMaterialProfile plugin reads them (plugins/XmlMaterialProfile/XmlMaterialProfile.py):
//
// Metadata: <metadata><name><brand/><material/><color/><label/></name>, <GUID>, ...; the container
// id and `base_file` are the file name without ".xml.fdm_material"; `approximate_diameter` is
// round(properties/diameter, default 2.85) with Python's round-half-even.
//
// Values ("setting map" of the plugin): <GUID> → material_guid, <properties><diameter> →
// material_diameter, and <settings><setting key=...>:
//   print temperature → default_material_print_temperature, heated bed temperature →
//   default_material_bed_temperature, standby temperature → material_standby_temperature,
//   processing temperature graph (<point flow= temperature=/>) → material_flow_temp_graph as
//   Python's str() of [[flow, temperature], ...] floats, print cooling → cool_fan_speed,
//   retraction amount/speed → retraction_amount/retraction_speed, adhesion tendency →
//   material_adhesion_tendency, surface energy → material_surface_energy, build volume
//   temperature → build_volume_temperature, anti ooze retract position/speed →
//   material_anti_ooze_retracted_position/material_anti_ooze_retraction_speed, break preparation
//   position/speed/temperature → material_break_preparation_retracted_position/_speed/_temperature,
//   break position/speed/temperature → material_break_retracted_position/material_break_speed/
//   material_break_temperature, flush purge speed/length, end of filament purge speed/length,
//   maximum park duration, no load move factor → the material_… keys of the same names.
//   "hardware compatible" sets the compatibility flag ("yes"/"unknown" → compatible); every other
//   key is ignored. <cura:setting key=K> sets the Cura setting K directly ("yes"/"no" → True/False).
//
// <machine> blocks (one per group of <machine_identifier product=...>) add or override values for
// those printers; <hotend id="AA 0.4"> blocks inside them add or override values for that nozzle.
// Not implemented (absent from fdm-materials 4.13): <inherits>, buildplate blocks inside hotends.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace mixengine {

using MaterialValues = std::map<std::string, std::string, std::less<>>;  ///< setting key → text

struct MaterialHotend {
    std::string name;  ///< the hotend id as written, e.g. "AA 0.4" or "0.4 mm"
    bool compatible = true;
    MaterialValues values;  ///< this block's own values only
};

struct MaterialMachineBlock {
    std::vector<std::string> products;  ///< machine_identifier product attributes
    bool compatible = true;
    MaterialValues values;  ///< this block's own values only
    std::vector<MaterialHotend> hotends;
};

struct MaterialProfile {
    std::string base_file;                                     ///< file name without ".xml.fdm_material"
    std::string source;                                        ///< path for messages
    std::string guid, brand, material, color_name, name;       ///< Cura's metadata of the same names
    std::map<std::string, std::string, std::less<>> metadata;  ///< every <metadata> child (local name → text)
    int approximate_diameter = 3;
    bool compatible = true;
    MaterialValues values;  ///< the values every container of this file has
    std::vector<MaterialMachineBlock> machines;
};

/// One material container Cura derives from a profile (base, machine-specific, or machine- and
/// hotend-specific), with its complete values.
struct MaterialContainer {
    std::string
        id;  ///< e.g. "generic_pla", "generic_pla_175_creality_ender3", "generic_pla_ultimaker_s5_AA_0.4"
    std::string definition;    ///< "fdmprinter" or the machine's definition id
    std::string variant_name;  ///< the hotend name; "" when not hotend-specific
    bool compatible = true;
    const MaterialProfile* profile = nullptr;
    MaterialValues values;
};

/// Parses a material file's text. Throws InputError naming `source` on malformed XML or when the
/// root is not an <fdmmaterial>.
MaterialProfile parseMaterialProfile(std::string_view text, std::string base_file, std::string source);

/// Reads and parses `path`; throws InputError naming the file.
MaterialProfile readMaterialFile(const std::filesystem::path& path);

/// The definition ids a <machine_identifier product=...> stands for: the plugin's
/// product_to_id.json entry when there is one, else its guesses from the name (lower case with
/// spaces removed, with '_' for spaces, and with digits glued to the word before: "ultimaker3_extended").
std::vector<std::string> productDefinitionIds(const std::string& product);

/// The containers of `profile` that Cura registers for `machine_id`, in Cura's registration order:
/// the base container (definition fdmprinter), then for each <machine> block naming the machine its
/// machine-specific container and one per <hotend>.
std::vector<MaterialContainer> materialContainersFor(const MaterialProfile& profile,
                                                     const std::string& machine_id);

}  // namespace mixengine
