// Whether a gather's ray sets pay for cheap rays, and how many (see SideDirectCache): what the
// pilot's sets tell. Per set, F is its value from its exact rays and G the control's mean at
// their landings (their elements' cached direct light). With M cheap rays a set's value is F − G
// plus the cheap rays' mean of the control, of variance var(F − G) + var(G)·n/M for n exact
// rays, where the plain set's is var(F). In the cove lobby F − G holds about 1 % of F's variance;
// where the books' spines face the points, three quarters: there cheap rays only add cost.
#pragma once

namespace radiant {

/// Sums over a sensor set's points of the sample variances of their sets' values F, F − G and G
/// (lux²), and the sets and the rays they cast.
struct ControlPilot {
    double plain = 0, residual = 0, control = 0;
    double sets = 0, rays = 0;
};

/// The cheap rays per set that leave a set's variance times its cost least, if that gains
/// enough over none (0 otherwise), for sets of `exact_rays` rays each.
int cheap_rays_per_set(const ControlPilot& pilot, int exact_rays);

}  // namespace radiant
