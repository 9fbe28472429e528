#pragma once
// The plan's table of distinct mixes (PrintPlan::mixes): each mix stored once, found again by value.
// Continuous values (a field's own mix, the commands that lead the chamber) are rounded to 1/1000 of a
// share first (roundedMix), so near-equal ones share an entry.
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "planning/MixVector.h"

namespace mixengine {

class MixTable {
  public:
    explicit MixTable(std::vector<MixVector>& mixes) : mixes_(mixes) {}
    /// The index of `mix` in the table, added at the end when it is not there yet.
    int indexOf(const MixVector& mix) {
        auto [it, added] = index_.emplace(mix, static_cast<int>(mixes_.size()));
        if (added)
            mixes_.push_back(mix);
        return it->second;
    }

  private:
    struct Less {
        bool operator()(const MixVector& a, const MixVector& b) const { return a.share < b.share; }
    };
    std::vector<MixVector>& mixes_;
    std::map<MixVector, int, Less> index_;
};

/// `mix` rounded to 1/1000 of each share, the last channel taking the rest (never below 0).
inline MixVector roundedMix(const MixVector& mix) {
    MixVector out = mix;
    double rest = 1.0;
    for (int c = 0; c + 1 < mix.channels; ++c) {
        out[c] = std::clamp(std::round(mix[c] * 1000.0) / 1000.0, 0.0, rest);
        rest -= out[c];
    }
    out[mix.channels - 1] = std::max(0.0, rest);
    return out;
}

}  // namespace mixengine
