#include "gcode/mixdialect/MixDialect.h"

#include "gcode/mixdialect/MixSplitAxes.h"
#include "gcode/mixdialect/MixTotalAxis.h"

namespace mixengine {

std::unique_ptr<MixDialect> makeMixDialect(const MixingOutput& mixing, bool relative_extrusion) {
    if (mixing.enabled()) {
        switch (mixing.dialect) {
            case MixDialectKind::EbAxes:
            case MixDialectKind::KlipperB:
            case MixDialectKind::RrfColon:
                return std::make_unique<MixSplitAxes>(mixing, relative_extrusion);
            default:
                break;
        }
    }
    return std::make_unique<MixTotalAxis>(mixing, relative_extrusion);
}

}  // namespace mixengine
