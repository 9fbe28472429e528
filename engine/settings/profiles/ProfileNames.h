#pragma once
// How the names a user gives (--variant, --material, ...) are matched to containers; the rules are
// listed in settings/profiles/ProfileSelector.h. Every failure is an InputError naming the machine,
// the extruder where it matters, the name, and (shortly) what is available.
#include <string>
#include <vector>

#include "settings/profiles/ContainerTree.h"

namespace mixengine {

/// Splits "a,b" into one name per extruder; one name applies to all; "" gives all "" (defaults).
/// Throws when there are more names than extruders.
std::vector<std::string> namesPerExtruder(const std::string& names, int extruder_count, const char* option);

/// "a, b, c" — at most `limit` entries, then "… (N more)"; "(none)" when empty.
std::string shortList(const std::vector<std::string>& names, std::size_t limit = 12);

/// The variant called `name` (rules in ProfileSelector.h).
const VariantEntry& findVariant(const ContainerTree& tree, const std::string& name);

/// The material called `name` among those of `variant_name`, for filament of `approximate_diameter`
/// millimetres (rounded). `extruder` is only used in messages.
const MaterialContainer& findMaterial(const ContainerTree& tree, const std::string& variant_name,
                                      int approximate_diameter, const std::string& name, int extruder);

}  // namespace mixengine
