#pragma once
// Which of Cura's profile containers to stack under the user's values (settings/ProfileStack.h),
// as the user names them (--variant/--material/--quality/--intent) or Cura's frontend sends them.
// Plain data; settings/profiles/ProfileSelector.h turns it into a ProfileStack and documents the
// accepted names.
#include <string>

namespace mixengine {

/// Empty names mean the machine's default (its metadata: preferred_variant_name, preferred_material,
/// preferred_quality_type); `enabled` false means definitions only, as CuraEngine's CLI does.
struct ProfileSelection {
    bool enabled = false;
    std::string variant, material, quality, intent;
};

}  // namespace mixengine
