#include "design/requirements.h"

#include <algorithm>

namespace radiant {
namespace {

// EN 12464-1:2011 Table 1: (task Ēm at least, surrounding Ēm); below the last row the
// surrounding needs what the task needs.
constexpr std::pair<double, double> kSurroundingSteps[] = {{750, 500}, {500, 300}, {300, 200}};
constexpr double kSurroundingU0 = 0.40;

// EN 12464-1:2011 Table 5.26 (offices): Ēm, U₀, UGR_L, Ra.
constexpr Activity kOffices[] = {
    {"5.26.1", "Filing, copying, etc.", 300, 0.40, 19, 80},
    {"5.26.2", "Writing, typing, reading, data processing", 500, 0.60, 19, 80},
    {"5.26.3", "Technical drawing", 750, 0.70, 16, 80},
    {"5.26.4", "CAD work stations", 500, 0.60, 19, 80},
    {"5.26.5", "Conference and meeting rooms", 500, 0.60, 19, 80},
    {"5.26.6", "Reception desk", 300, 0.60, 22, 80},
    {"5.26.7", "Archives", 200, 0.40, 25, 80},
};

}  // namespace

std::span<const Activity> en12464_activities() { return kOffices; }

const Activity* find_activity(std::string_view reference) {
    const std::span<const Activity> table = en12464_activities();
    const auto it = std::find_if(table.begin(), table.end(),
                                 [&](const Activity& a) { return a.reference == reference; });
    return it == table.end() ? nullptr : &*it;
}

AppliedRequirement apply_requirement(const Requirement& r) {
    AppliedRequirement out;
    out.source = "scene";
    if (r.activity) {
        if (const Activity* a = find_activity(*r.activity)) {
            out.source = "table";
            out.activity = std::string(a->reference) + " " + std::string(a->name);
            out.em_lx = a->em_lx;
            out.u0 = a->u0;
            out.ugr_l = a->ugr_l;
            out.ra = a->ra;
        }
    }
    if (r.em_lx) out.em_lx = r.em_lx;
    if (r.u0) out.u0 = r.u0;
    if (r.ugr_l) out.ugr_l = r.ugr_l;
    if (r.ra) out.ra = r.ra;
    return out;
}

AppliedRequirement surrounding_requirement(const AppliedRequirement& task) {
    AppliedRequirement out;
    out.source = "surrounding";
    out.activity = task.activity;
    if (task.em_lx) {
        out.em_lx = *task.em_lx;
        for (const auto& [at_least, surrounding] : kSurroundingSteps) {
            if (*task.em_lx >= at_least) {
                out.em_lx = surrounding;
                break;
            }
        }
    }
    out.u0 = kSurroundingU0;
    return out;
}

}  // namespace radiant
