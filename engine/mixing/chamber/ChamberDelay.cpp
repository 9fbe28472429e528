#include "mixing/chamber/ChamberDelay.h"

namespace mixengine {

std::vector<int> delayCompensated(const std::vector<int>& target, const std::vector<double>& volume_mm3,
                                  double chamber_mm3) {
    if (chamber_mm3 <= 0 || target.empty())
        return target;
    std::vector<int> commanded(target.size());
    std::size_t ahead = 0;   // the extrusion holding the look-up point
    double ahead_start = 0;  // cumulative volume where `ahead` starts
    double start = 0;        // cumulative volume where extrusion i starts
    for (std::size_t i = 0; i < target.size(); ++i) {
        const double point = start + volume_mm3[i] / 2.0 + chamber_mm3;
        while (ahead + 1 < target.size() && ahead_start + volume_mm3[ahead] <= point) {
            ahead_start += volume_mm3[ahead];
            ++ahead;
        }
        commanded[i] = target[ahead];
        start += volume_mm3[i];
    }
    return commanded;
}

}  // namespace mixengine
