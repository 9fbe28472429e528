#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

Feature markedFeature(Feature feature) {
    switch (feature) {
        case Feature::Ironing:
        case Feature::Roofing:
            return Feature::Skin;
        case Feature::RaftBase:
        case Feature::RaftSurface:
        case Feature::SupportBottom:
            return Feature::SupportInterface;
        case Feature::RaftInterface:
            return Feature::Support;
        case Feature::DraftShield:
            return Feature::Skirt;
        default:
            return feature;
    }
}

std::string_view featureMarker(Feature feature) {
    switch (markedFeature(feature)) {
        case Feature::WallOuter:
            return "WALL-OUTER";
        case Feature::WallInner:
            return "WALL-INNER";
        case Feature::Skin:
            return "SKIN";
        case Feature::Support:
            return "SUPPORT";
        case Feature::SupportInterface:
            return "SUPPORT-INTERFACE";
        case Feature::Skirt:
            return "SKIRT";
        case Feature::PrimeTower:
            return "PRIME-TOWER";
        default:
            return "FILL";
    }
}

}  // namespace mixengine
