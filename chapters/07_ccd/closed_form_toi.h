#pragma once
// Times of impact in closed form, for spheres moving without turning (a sphere's rotation does
// not move its surface): the swept-sphere tests of Ericson, Real-Time Collision Detection
// (2005), 5.5.3 (sphere against plane) and 5.5.5 (sphere against sphere). The stage takes the
// second for sphere pairs; both are the oracles conservative advancement is tested against.

#include "07_ccd/time_of_impact.h"

#include <optional>

namespace stepwise {

/// A sphere whose centre moves from center0 to center0 + travel over t in [0, 1], against the
/// plane dot(planeNormal, x) = planeOffset (unit normal, the sphere in front of it): the first t
/// at which the sphere's surface is `target` from the plane; nullopt when it never gets there in
/// the step. 0 when it starts within the target.
std::optional<Real> spherePlaneTimeOfImpact(const Vec3& center0, const Vec3& travel, Real radius,
                                            const Vec3& planeNormal, Real planeOffset, Real target);

/// Two spheres moving by travelA and travelB over t in [0, 1]: the first t at which their
/// surfaces are `target` apart; nullopt when they do not get there in the step, 0 when they
/// start within it.
std::optional<Real> sphereSphereTimeOfImpact(const Vec3& centerA, const Vec3& travelA, Real radiusA,
                                             const Vec3& centerB, const Vec3& travelB, Real radiusB, Real target);

/// The same for two sphere sweeps, as a ToiResult (time, normal, points) from max(alpha0s) on.
ToiResult sphereSweepsTimeOfImpact(Real radiusA, const Sweep& a, Real radiusB, const Sweep& b, const ToiOptions& options);

}  // namespace stepwise
