#include "toolpaths/walls/OutlineOffsets.h"

#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"

namespace mixengine {

Paths offsetOutlines(const Paths& outlines, coord_um xy_offset_um, coord_um hole_offset_um) {
    Paths result = xy_offset_um != 0 ? offsetPolygons(outlines, xy_offset_um) : outlines;
    if (hole_offset_um == 0)
        return result;
    Paths outer, holes;
    for (const Path& loop : result) {
        if (counterClockwise(loop)) {
            outer.push_back(loop);
        } else {
            Path as_area(loop.rbegin(), loop.rend());  // the hole as an area of its own
            for (const Path& grown : offsetMiter({as_area}, hole_offset_um))  // CuraEngine: mitred
                holes.push_back(grown);
        }
    }
    return differenceOf(unionOf(outer), unionOf(holes));
}

}  // namespace mixengine
