#pragma once
// The orientation pass's result as text (printed by `mixengine orient`) and as JSON (--report).
#include <nlohmann/json.hpp>
#include <string>

#include "orient/Orienter.h"

namespace mixengine::orient {

/// Names of the two parts for the texts.
struct PartNames {
    std::string a, b;
};

std::string resultText(const OrientResult& result, const PartNames& names);

/// Keys: method, measure, offset_mm, centre_mm, latitude_deg, longitude_deg, spin_deg, rotation
/// (3×3, rows), direction, picked_by, score {contact_mm2, height_mm, overhang_mm2}, parts
/// [{name, volume_mm3, solid}], exact, v_before_mm3, v_after_mm3, v_before_estimate_mm3,
/// v_after_estimate_mm3, candidates [...], warnings, evaluations, time_s {...}, map {step_deg,
/// rows, columns, exact}.
nlohmann::json resultJson(const OrientResult& result, const PartNames& names);

}  // namespace mixengine::orient
