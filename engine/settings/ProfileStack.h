#pragma once
// The containers Cura stacks between a machine's definitions and the user's values: intent,
// quality, material and variant (nozzle) profiles, for the global stack and for each extruder
// train. Values are text, or formulas (Cura writes those with a leading '=' in .inst.cfg files).
//
// Lookup order inside StackEvaluator, first hit wins (Cura's own order):
//   extruder N: -eN user, extruder N's containers (top first), the extruder definition, global user,
//               the global containers, the machine definition;
//   global:     global user, the global containers, the machine definition.
// Without Cura's stacks (ProfileStack::cura false) the global user values come right after -eN's.
#include <map>
#include <string>
#include <vector>

namespace mixengine {

struct ContainerValue {
    std::string text;  ///< literal text, or the formula when is_formula
    bool is_formula = false;
};

struct InstanceContainer {
    std::string id;    ///< e.g. "creality_base_global_standard" or "generic_pla"
    std::string type;  ///< "intent", "quality", "material", "variant", ...
    std::map<std::string, ContainerValue, std::less<>> values;
};

struct ProfileStack {
    /// The stacks of Cura's frontend (--profiles): StackEvaluator then resolves as Cura 4.13 does
    /// (see settings/StackEvaluator.h, "Cura's frontend"). False: definitions and user values only,
    /// as CuraEngine's command line.
    bool cura = false;
    std::vector<InstanceContainer> global;                    ///< top first
    std::map<int, std::vector<InstanceContainer>> extruders;  ///< by extruder_nr, top first
};

}  // namespace mixengine
