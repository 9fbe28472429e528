#include "orient/OrientReport.h"

#include <cstdio>

namespace mixengine::orient {
namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

nlohmann::json vec(const Vec3& v) {
    return {v.x, v.y, v.z};
}

std::string matrixText(const Matrix3& m) {
    std::string out = "[";
    for (int i = 0; i < 3; ++i) {
        out += i ? ", [" : "[";
        for (int j = 0; j < 3; ++j)
            out += (j ? ", " : "") + format("%.6f", m.m[i][j] == 0 ? 0.0 : m.m[i][j]);
        out += "]";
    }
    return out + "]";
}

}  // namespace

std::string resultText(const OrientResult& r, const PartNames& names) {
    const std::string kind = r.exact ? "exact" : "voxel estimate";
    std::string out;
    out += "parts: A = " + names.a + " (" + format("%.1f", r.volume_a_mm3) + " mm³, " + r.solid_a +
           "), B = " + names.b + " (" + format("%.1f", r.volume_b_mm3) + " mm³, " + r.solid_b + ")\n";
    out +=
        "nozzle offset d = (" + format("%g", r.offset_mm.x) + ", " + format("%g", r.offset_mm.y) +
        ") mm; measure: " + (r.measure == Measure::OwnPart ? "own part (seed 000)" : "all material (A ∪ B)") +
        "; method: " + methodName(r.method) + " (" + std::to_string(r.evaluations) + " evaluations)\n";
    out += "best: latitude " + format("%.2f", r.angles.latitude_deg) + "°, longitude " +
           format("%.2f", r.angles.longitude_deg) + "°, spin about d " + format("%.2f", r.spin_deg) + "°\n";
    out += "picked by: " + r.picked_by + " (bed contact " + format("%.1f", r.score.contact_mm2) +
           " mm², height " + format("%.2f", r.score.height_mm) + " mm, overhang " +
           format("%.1f", r.score.overhang_mm2) + " mm²)\n";
    out += "rotation matrix: " + matrixText(r.rotation) + "\n";
    out += "V before: " + format("%.3f", r.v_before_mm3) + " mm³ (" + kind + "; voxel " +
           format("%.3f", r.v_before_estimate_mm3) + ")\n";
    out += "V after:  " + format("%.3f", r.v_after_mm3) + " mm³ (" + kind + "; voxel " +
           format("%.3f", r.v_after_estimate_mm3) + ")\n";
    out += "time: " + format("%.3f", r.time.total_s) + " s (checks " + format("%.3f", r.time.check_s) +
           ", voxels+FFT " + format("%.3f", r.time.voxel_s) + ", search " + format("%.3f", r.time.search_s) +
           ", exact " + format("%.3f", r.time.exact_s) + ", spin " + format("%.3f", r.time.spin_s) + ")\n";
    return out;
}

nlohmann::json resultJson(const OrientResult& r, const PartNames& names) {
    nlohmann::json doc;
    doc["method"] = methodName(r.method);
    doc["measure"] = measureName(r.measure);
    doc["offset_mm"] = vec(r.offset_mm);
    doc["centre_mm"] = vec(r.centre_mm);
    doc["latitude_deg"] = r.angles.latitude_deg;
    doc["longitude_deg"] = r.angles.longitude_deg;
    doc["spin_deg"] = r.spin_deg;
    for (int i = 0; i < 3; ++i)
        doc["rotation"].push_back({r.rotation.m[i][0], r.rotation.m[i][1], r.rotation.m[i][2]});
    doc["direction"] = vec(r.direction);
    doc["picked_by"] = r.picked_by;
    doc["score"] = {{"contact_mm2", r.score.contact_mm2},
                    {"height_mm", r.score.height_mm},
                    {"overhang_mm2", r.score.overhang_mm2}};
    doc["parts"] = {{{"name", names.a}, {"volume_mm3", r.volume_a_mm3}, {"solid", r.solid_a}},
                    {{"name", names.b}, {"volume_mm3", r.volume_b_mm3}, {"solid", r.solid_b}}};
    doc["exact"] = r.exact;
    doc["v_before_mm3"] = r.v_before_mm3;
    doc["v_after_mm3"] = r.v_after_mm3;
    doc["v_before_estimate_mm3"] = r.v_before_estimate_mm3;
    doc["v_after_estimate_mm3"] = r.v_after_estimate_mm3;
    doc["candidates"] = nlohmann::json::array();
    for (const CandidateReport& c : r.candidates) {
        doc["candidates"].push_back(
            {{"direction", vec(c.u)},
             {"latitude_deg", c.angles.latitude_deg},
             {"longitude_deg", c.angles.longitude_deg},
             {"source", c.source},
             {"v_estimate_mm3", c.v_estimate_mm3},
             {"v_exact_mm3", c.v_exact_mm3 ? nlohmann::json(*c.v_exact_mm3) : nullptr}});
    }
    doc["warnings"] = r.warnings;
    doc["evaluations"] = r.evaluations;
    doc["time_s"] = {{"total", r.time.total_s},   {"checks", r.time.check_s}, {"voxels_fft", r.time.voxel_s},
                     {"search", r.time.search_s}, {"exact", r.time.exact_s},  {"spin", r.time.spin_s}};
    doc["map"] = {{"step_deg", r.map.step_deg},
                  {"rows", r.map.rows},
                  {"columns", r.map.columns},
                  {"exact", r.map.exact},
                  {"values_mm3", r.map.values}};
    return doc;
}

}  // namespace mixengine::orient
