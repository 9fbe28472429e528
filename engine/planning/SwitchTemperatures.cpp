#include "planning/SwitchTemperatures.h"

#include <algorithm>
#include <optional>

#include "planning/ExtruderRuns.h"
#include "planning/PreheatModel.h"

namespace mixengine {

std::vector<TrainTemperatureParams> trainTemperatureParams(const std::vector<Settings>& extruders) {
    std::vector<TrainTemperatureParams> out;
    for (const Settings& e : extruders) {
        TrainTemperatureParams t;
        t.nozzle = nozzleTemperatureParams(e);
        t.initial_c = e.temperatureCelsius(key::material_initial_print_temperature);
        t.final_c = e.temperatureCelsius(key::material_final_print_temperature);
        t.standby_c = e.temperatureCelsius(key::material_standby_temperature);
        t.min_window_s = e.durationSeconds(key::machine_min_cool_heat_time_window);
        out.push_back(t);
    }
    return out;
}

namespace {

constexpr std::size_t kLayersInView = 5;  ///< CuraEngine's buffer: the newest layer and 5 before it
constexpr double kExtraPreheatS = 1.0;    ///< heat this much earlier than computed

/// What the rules decide for one run.
struct RunTemperatures {
    double start_c = 0;                         ///< required when the run starts
    std::optional<double> printing_c;           ///< set at its first extrusion (with an initial temperature)
    double heated_before_s = 0;                 ///< time before its first extrusion path ends
    std::optional<double> standby_of_previous;  ///< for the extruder switched away from
    int reheat = -1;                            ///< index of the same-extruder preheat set in this run
};

struct Insert {
    std::size_t layer = 0;
    std::size_t at = 0;  ///< before this step of the layer
    int order = 0;       ///< switch commands first, then in the order made
    PlanStep step;
    bool dropped = false;
};

PlanStep nozzleStep(int extruder, double celsius, bool wait) {
    PlanStep step;
    step.kind = PlanStep::Kind::SetNozzleTemperature;
    step.extruder = extruder;
    step.temperature_c = celsius;
    step.wait = wait;
    return step;
}

class Planner {
  public:
    Planner(PrintPlan& plan, const SwitchTemperatureParams& params, int start_extruder, Point2 start)
        : plan_(plan),
          params_(params),
          runs_(extruderRuns(plan, start_extruder, start)),
          temps_(runs_.runs.size()),
          used_(params.trains.size(), false) {}

    void run() {
        for (std::size_t i = 0; i < runs_.runs.size(); ++i) {
            decideStart(i);
            if (i > 0)
                placeCommands(i);
        }
        addSwitchCommands();
        apply();
    }

  private:
    const ExtruderRun& at(std::size_t i) const { return runs_.runs[i]; }
    const TrainTemperatureParams& train(int extruder) const {
        return params_
            .trains[std::min<std::size_t>(static_cast<std::size_t>(extruder), params_.trains.size() - 1)];
    }
    HeaterRates rates(int extruder) const {
        const NozzleTemperatureParams& n = train(extruder).nozzle;
        return {n.heat_up_c_per_s, n.cool_down_c_per_s, n.extrusion_cool_c_per_s};
    }
    bool controlled(int extruder) const { return train(extruder).nozzle.enabled; }
    double stepS(std::size_t layer, std::size_t step) const { return runs_.step_seconds[layer][step]; }

    /// The first run index still in view when run i is planned.
    std::size_t firstInView(std::size_t i) const {
        std::size_t first = i;
        while (first > 0 && at(first - 1).layer + kLayersInView >= at(i).layer)
            --first;
        return first;
    }

    double printingTemperature(const ExtruderRun& r) const {
        const NozzleTemperatureParams& n = train(r.extruder).nozzle;
        if (plan_.layers[r.layer].index == 0 && n.layer0_c != 0)
            return n.layer0_c;
        return flowTemperature(n, r.unretracted_s > 0 ? r.volume_mm3 / r.unretracted_s : 0.0);
    }

    void decideStart(std::size_t i) {
        const ExtruderRun& r = at(i);
        const double printing = printingTemperature(r);
        const TrainTemperatureParams& t = train(r.extruder);
        const bool own_before = i > 0 && at(i - 1).extruder == r.extruder && at(i - 1).unretracted_s > 0;
        const auto e = static_cast<std::size_t>(r.extruder);
        if (t.initial_c == 0 || params_.share_heater || e >= used_.size() || !used_[e] || own_before) {
            temps_[i].start_c = printing;
            if (e < used_.size())
                used_[e] = true;
        } else {
            temps_[i].start_c = t.initial_c;
            temps_[i].printing_c = printing;
        }
    }

    void placeCommands(std::size_t i) {
        const ExtruderRun& r = at(i);
        const ExtruderRun& before = at(i - 1);
        if (before.extruder != r.extruder)
            temps_[i].standby_of_previous = train(before.extruder).standby_c;
        if (before.extruder == r.extruder) {
            temps_[i - 1].reheat = preheatSameExtruder(i - 1, r.extruder, temps_[i].start_c);
        } else if (params_.share_heater) {
            preheatSameExtruder(i - 1, before.extruder, temps_[i].start_c);
        } else {
            preheatAfterStandby(i);
            finalTemperature(i - 1, firstInView(i));
            printingTemperatureCommand(i);
        }
    }

    /// Adds `step` to run r so that about `before_end_s` of the run's time follows it; returns its index.
    int insertBeforeEnd(std::size_t r, double before_end_s, const PlanStep& step) {
        const ExtruderRun& run = at(r);
        std::size_t pos = run.begin;
        double after = 0;
        for (std::size_t s = run.end; s-- > run.begin;) {
            after += stepS(run.layer, s);
            if (after > before_end_s) {
                pos = s;
                break;
            }
        }
        return add(run.layer, pos, step);
    }

    int add(std::size_t layer, std::size_t pos, const PlanStep& step, int order = 0) {
        inserts_.push_back({layer, pos, order, step});
        return static_cast<int>(inserts_.size()) - 1;
    }

    int preheatSameExtruder(std::size_t r, int extruder, double target_c) {
        if (!controlled(extruder))
            return -1;
        const double from_c = temps_[r].printing_c.value_or(temps_[r].start_c);
        const double lead_s =
            std::min(at(r).seconds, 0.5 * secondsToReach(rates(extruder), from_c, target_c, true));
        return insertBeforeEnd(r, lead_s, nozzleStep(extruder, target_c, false));
    }

    /// How the extruder of run i cools while idle and when it must heat (CuraEngine's standby plan).
    WarmUp standbyPlan(std::size_t i) const {
        const int extruder = at(i).extruder;
        const TrainTemperatureParams& t = train(extruder);
        const double target_c = temps_[i].start_c;
        double idle_s = 0;
        for (std::size_t j = i; j-- > firstInView(i);) {
            if (at(j).extruder == extruder) {
                const double left_c = t.final_c != 0 ? t.final_c : temps_[j].printing_c.value_or(target_c);
                WarmUp w = warmUpAfterCoolDown(rates(extruder), idle_s, left_c, t.standby_c, target_c, false);
                w.heating_s = std::min(idle_s, w.heating_s + kExtraPreheatS);
                return w;
            }
            idle_s += at(j).seconds;
        }
        WarmUp w{idle_s, secondsToReach(rates(extruder), t.standby_c, target_c, false), t.standby_c};
        if (w.heating_s > idle_s) {  // not in view for long enough to have cooled all the way
            w.heating_s = idle_s;
            w.lowest_c = target_c - idle_s * t.nozzle.heat_up_c_per_s;
        }
        w.heating_s += kExtraPreheatS;
        return w;
    }

    /// The temperature the extruder of run i is left at when switched away from before it.
    void leaveAt(std::size_t i, double celsius) {
        const int extruder = at(i).extruder;
        const std::size_t first = firstInView(i);
        for (std::size_t j = i - 1; j-- > first;) {
            if (at(j).extruder == extruder) {
                temps_[j + 1].standby_of_previous = celsius;
                return;
            }
        }
        const ExtruderRun& earliest = at(first);
        add(earliest.layer, earliest.begin, nozzleStep(extruder, celsius, false));
    }

    void preheatAfterStandby(std::size_t i) {
        const int extruder = at(i).extruder;
        if (!controlled(extruder))
            return;
        const double target_c = temps_[i].start_c;
        const WarmUp w = standbyPlan(i);
        if (w.window_s < train(extruder).min_window_s) {
            leaveAt(i, target_c);
            return;  // stays at the printing temperature
        }
        if (w.heating_s < w.window_s)
            leaveAt(i, w.lowest_c);
        double lead_s = w.heating_s;
        const std::size_t first = firstInView(i);
        for (std::size_t j = i; j-- > first;) {
            if (at(j).seconds >= lead_s) {
                insertBeforeEnd(j, lead_s, nozzleStep(extruder, target_c, false));
                return;
            }
            lead_s -= at(j).seconds;
        }
        add(at(first).layer, at(first).begin, nozzleStep(extruder, target_c, false));
    }

    /// Time at the end of run r after its last extrusion.
    double travelAfterLastExtrusion(std::size_t r) const {
        double seconds = 0;
        for (std::size_t s = at(r).end; s-- > at(r).begin;) {
            if (plan_.layers[at(r).layer].steps[s].kind == PlanStep::Kind::Extrude)
                break;
            seconds += stepS(at(r).layer, s);
        }
        return seconds;
    }

    struct Stretch {
        double window_s = 0;
        double average_c = 0;
        std::optional<double> first_start_c;
    };

    /// The extruder's runs up to `last` since the switch to it: printing time and average temperature.
    Stretch stretchUpTo(std::size_t last, std::size_t first_in_view) const {
        Stretch s;
        double heated_before_s = 0;
        for (std::size_t j = last + 1; j-- > first_in_view && at(j).extruder == at(last).extruder;) {
            s.window_s += at(j).seconds;
            heated_before_s = temps_[j].heated_before_s;
            if (at(j).unretracted_s > 0) {
                s.average_c += temps_[j].printing_c.value_or(temps_[j].start_c) * at(j).seconds;
                s.first_start_c = temps_[j].start_c;
            }
        }
        if (s.window_s > 0)
            s.average_c /= s.window_s;
        s.window_s -= heated_before_s + travelAfterLastExtrusion(last);
        return s;
    }

    void finalTemperature(std::size_t last, std::size_t first_in_view) {
        const int extruder = at(last).extruder;
        const double final_c = train(extruder).final_c;
        if (!controlled(extruder) || final_c == 0)
            return;
        const Stretch s = stretchUpTo(last, first_in_view);
        if (!s.first_start_c)
            return;
        double cool_s =
            coolDownAfterWarmUp(rates(extruder), s.window_s, *s.first_start_c, s.average_c, final_c, true)
                .cooling_s;
        std::size_t r = last;
        for (std::size_t j = last + 1; j-- > first_in_view;) {
            r = j;
            if (temps_[j].reheat >= 0)
                inserts_[static_cast<std::size_t>(temps_[j].reheat)].dropped = true;
            if (cool_s < at(j).seconds)
                break;
            cool_s -= at(j).seconds;
        }
        insertCoolDown(r, cool_s, nozzleStep(extruder, final_c, false));
    }

    /// As insertBeforeEnd, but at the run's end when the run is shorter (CuraEngine's precool).
    void insertCoolDown(std::size_t r, double before_end_s, const PlanStep& step) {
        const ExtruderRun& run = at(r);
        double after = 0;
        for (std::size_t s = run.end; s-- > run.begin;) {
            after += stepS(run.layer, s);
            if (after >= before_end_s) {
                add(run.layer, s, step);
                return;
            }
        }
        add(run.layer, run.end, step);
    }

    void printingTemperatureCommand(std::size_t i) {
        const ExtruderRun& r = at(i);
        if (!temps_[i].printing_c || !controlled(r.extruder) || train(r.extruder).initial_c == 0)
            return;
        const std::vector<PlanStep>& steps = plan_.layers[r.layer].steps;
        std::size_t s = r.begin;
        double before_s = 0;
        while (s < r.end && steps[s].kind != PlanStep::Kind::Extrude)
            before_s += stepS(r.layer, s++);
        const std::size_t first_extrusion = s;
        while (s < r.end && steps[s].kind == PlanStep::Kind::Extrude)  // the first path, as CuraEngine's
            before_s += stepS(r.layer, s++);
        add(r.layer, first_extrusion, nozzleStep(r.extruder, *temps_[i].printing_c, false));
        temps_[i].heated_before_s = before_s;
    }

    /// M109 for the start temperature and the standby of the extruder left, after each switch.
    void addSwitchCommands() {
        for (std::size_t i = 1; i < runs_.runs.size(); ++i) {
            const ExtruderRun& r = at(i);
            const int left = at(i - 1).extruder;
            if (left == r.extruder)
                continue;
            const std::size_t pos = r.begin;  // right after the SetExtruder step
            add(r.layer, pos, nozzleStep(r.extruder, temps_[i].start_c, true), -2);
            if (!temps_[i].standby_of_previous)
                continue;
            const auto l = static_cast<std::size_t>(left);
            const bool done =
                l < params_.last_layer.size() && params_.last_layer[l] <= plan_.layers[r.layer].index;
            add(r.layer, pos, nozzleStep(left, done ? 0.0 : *temps_[i].standby_of_previous, false), -1);
        }
    }

    void apply() {
        std::stable_sort(inserts_.begin(), inserts_.end(), [](const Insert& a, const Insert& b) {
            return a.layer != b.layer ? a.layer < b.layer : a.at != b.at ? a.at < b.at : a.order < b.order;
        });
        std::size_t k = 0;
        for (std::size_t l = 0; l < plan_.layers.size(); ++l) {
            std::vector<PlanStep> steps;
            const std::vector<PlanStep>& old = plan_.layers[l].steps;
            for (std::size_t s = 0; s <= old.size(); ++s) {
                for (; k < inserts_.size() && inserts_[k].layer == l && inserts_[k].at == s; ++k) {
                    if (!inserts_[k].dropped)
                        steps.push_back(inserts_[k].step);
                }
                if (s < old.size())
                    steps.push_back(old[s]);
            }
            plan_.layers[l].steps = std::move(steps);
        }
    }

    PrintPlan& plan_;
    const SwitchTemperatureParams& params_;
    ExtruderRuns runs_;
    std::vector<RunTemperatures> temps_;
    std::vector<bool> used_;
    std::vector<Insert> inserts_;
};

}  // namespace

void planSwitchTemperatures(PrintPlan& plan, const SwitchTemperatureParams& params, int start_extruder,
                            Point2 start) {
    if (params.trains.empty())
        return;
    Planner(plan, params, start_extruder, start).run();
}

}  // namespace mixengine
