#include "task_area_marks.h"

#include <algorithm>

#include "radiant/picture/false_colour.h"

namespace radiant::cli {
namespace {

picture::PlanVerdict::Mark mark_of(Check::Status status) {
    return status == Check::Status::pass   ? picture::PlanVerdict::Mark::pass
           : status == Check::Status::fail ? picture::PlanVerdict::Mark::fail
                                           : picture::PlanVerdict::Mark::unknown;
}

std::string status_word(Check::Status status) {
    return status == Check::Status::pass   ? "PASS"
           : status == Check::Status::fail ? "FAIL"
                                           : "UNKNOWN";
}

/// "Em 396 lx >= 500: FAIL" — plain ASCII, as the plan's font draws it.
std::string check_line(const Check& c) {
    const bool at_most = c.criterion == "ugr_l";
    const std::string name = c.criterion == "em_lx"   ? "Em"
                             : c.criterion == "u0"    ? "U0"
                             : c.criterion == "ugr_l" ? "UGR"
                                                      : "Ra";
    std::string text =
        name + " " +
        (c.status == Check::Status::unknown && !c.note.empty() ? std::string("?")
                                                               : picture::short_number(c.value)) +
        (c.criterion == "em_lx" ? " lx" : "") + (at_most ? " <= " : " >= ") +
        picture::short_number(c.required) + ": " + status_word(c.status);
    if (!c.observer.empty()) text += " (" + c.observer + ")";
    return text;
}

}  // namespace

void add_task_area_marks(const Scene& scene, const Result& result, std::size_t set,
                         picture::SensorPlan& plan) {
    const SensorSet& task = scene.sensors[set];
    const SensorResult& solved = result.sensors[set];
    if (!solved.compliance) return;
    if (task.grid) {
        plan.task_area = std::array<Vec3, 3>{task.grid->origin, task.grid->u, task.grid->v};
    } else if (task.grid_area) {
        plan.task_area =
            std::array<Vec3, 3>{task.grid_area->origin, task.grid_area->u, task.grid_area->v};
    }
    const Compliance& c = *solved.compliance;
    std::string heading("EN 12464-1 ");
    heading += c.requirement.activity.empty() ? std::string("requirement") : c.requirement.activity;
    heading += ": ";
    heading += status_word(c.status);
    plan.verdicts.push_back({heading, mark_of(c.status)});
    for (const Check& check : c.checks)
        plan.verdicts.push_back({check_line(check), mark_of(check.status)});
    for (std::size_t s = 0; s < scene.sensors.size(); ++s) {
        if (scene.sensors[s].surrounding_of != set || !result.sensors[s].compliance) continue;
        plan.band_points = scene.sensors[s].points;
        plan.band_lux = result.sensors[s].illuminance;
        const Compliance& band = *result.sensors[s].compliance;
        // Appended piece by piece: GCC 12 misreads "literal" + std::string&& (-Wrestrict).
        std::string line("surrounding band (hatched): ");
        line += status_word(band.status);
        const char* separator = " - ";
        for (const Check& check : band.checks) {
            line += separator;
            line += check_line(check);
            separator = "; ";
        }
        plan.verdicts.push_back({line, mark_of(band.status)});
    }
    for (const Observer& o : scene.observers) {
        if (!o.task || *o.task == task.name) plan.observers.push_back(o.position);
    }
}

}  // namespace radiant::cli
