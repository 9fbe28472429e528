#include "toolpaths/ExtrusionPath.h"

namespace mixengine {

std::string_view featureMarker(Feature feature) {
    switch (feature) {
        case Feature::WallOuter:
            return "WALL-OUTER";
        case Feature::WallInner:
            return "WALL-INNER";
        case Feature::Skin:
            return "SKIN";
        case Feature::Fill:
            return "FILL";
        case Feature::Support:
            return "SUPPORT";
        case Feature::SupportInterface:
            return "SUPPORT-INTERFACE";
        case Feature::Skirt:
            return "SKIRT";
        case Feature::PrimeTower:
            return "PRIME-TOWER";
    }
    return "FILL";
}

}  // namespace mixengine
