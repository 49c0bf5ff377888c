#include "design/compliance.h"

namespace radiant {
namespace {

Check::Status verdict(bool pass) { return pass ? Check::Status::pass : Check::Status::fail; }

}  // namespace

Compliance check_requirement(const AppliedRequirement& requirement, const SensorResult& set,
                             const std::vector<const ObserverResult*>& observers,
                             std::optional<double> ra) {
    Compliance out;
    out.requirement = requirement;
    if (requirement.em_lx) {
        out.checks.push_back({"em_lx", *requirement.em_lx, set.average,
                              verdict(set.average >= *requirement.em_lx), "", ""});
    }
    if (requirement.u0) {
        out.checks.push_back(
            {"u0", *requirement.u0, set.u0, verdict(set.u0 >= *requirement.u0), "", ""});
    }
    if (requirement.ugr_l) {
        Check c{"ugr_l", *requirement.ugr_l, 0, Check::Status::unknown, "", ""};
        for (const ObserverResult* o : observers) {
            if (c.observer.empty() || o->ugr > c.value) {
                c.value = o->ugr;
                c.observer = o->name;
            }
        }
        if (observers.empty()) {
            c.note = "no observer checks this task area";
        } else {
            c.status = verdict(c.value <= *requirement.ugr_l);
        }
        out.checks.push_back(std::move(c));
    }
    if (requirement.ra) {
        Check c{"ra", *requirement.ra, ra.value_or(0), Check::Status::unknown, "", ""};
        if (ra) {
            c.status = verdict(*ra >= *requirement.ra);
        } else {
            c.note = "a luminaire or emitting material that lights the scene gives no ra";
        }
        out.checks.push_back(std::move(c));
    }
    out.status = Check::Status::pass;
    for (const Check& c : out.checks) {
        if (c.status == Check::Status::fail) {
            out.status = Check::Status::fail;
            break;
        }
        if (c.status == Check::Status::unknown) out.status = Check::Status::unknown;
    }
    return out;
}

}  // namespace radiant
