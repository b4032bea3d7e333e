// The reference suite's metrics (reference.h): each compares a recorded run with a closed form
// or a conservation law and returns the error in the check's units.
#include "engine/reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stepwise::engine_bench {

namespace {

Vec3 centreOfMass(const World& world, int body, const Transform& pose) {
    const Motion* motion = world.motionOf(body);
    return pose.apply(motion ? motion->localCenter : Vec3::Zero());
}

/// The centre of mass of `body` at every recorded frame.
std::vector<Vec3> path(const Trajectory& run, int body) {
    std::vector<Vec3> points;
    for (const std::vector<Transform>& frame : run.poses) points.push_back(centreOfMass(run.start, body, frame[body]));
    return points;
}

std::vector<int> dynamicBodies(const World& world) {
    std::vector<int> list;
    for (int i = 0; i < static_cast<int>(world.bodies.size()); ++i)
        if (world.bodies[i].type == BodyType::Dynamic) list.push_back(i);
    return list;
}

/// Projectile: x(t) = x0 + v0 t + g t^2 / 2 is exact without contacts.
double projectileError(const Trajectory& run, int body) {
    const std::vector<Vec3> points = path(run, body);
    const Vec3 v0 = run.start.motionOf(body)->linearVelocity;
    const Vec3 g = run.start.settings.gravity;
    double worst = 0;
    for (std::size_t f = 0; f < points.size(); ++f) {
        const Real t = Real(f * run.dt);
        worst = std::max(worst, double((points[f] - (points[0] + v0 * t + g * (t * t / 2))).norm()));
    }
    return worst;
}

/// Torque-free spin about a principal axis: the angular velocity stays w, so q(t) = exp(w t) q0.
double spinError(const Trajectory& run, int body) {
    const Vec3 w = run.start.motionOf(body)->angularVelocity;
    const Quat q0 = run.poses.front()[body].rotation;
    double worst = 0;
    for (std::size_t f = 0; f < run.poses.size(); ++f) {
        const double angle = double(w.norm()) * double(f) * run.dt;
        const Quat turn(Eigen::AngleAxis<Real>(Real(angle), w.norm() > 0 ? Vec3(w.normalized()) : Vec3::UnitX()));
        const double dot = std::min(1.0, std::abs(double((turn * q0).dot(run.poses[f][body].rotation))));
        worst = std::max(worst, 2 * std::acos(dot));
    }
    return worst;
}

/// The height of the first apex after the first bounce: the body falls, turns up, and the
/// highest point before it falls again. A body that never turns up answers its lowest point.
double bounceApex(const Trajectory& run, int body) {
    const std::vector<Vec3> points = path(run, body);
    std::size_t f = 1;
    bool fell = false;
    for (; f < points.size(); ++f) {
        const Real rise = points[f].y() - points[f - 1].y();
        if (rise < 0) fell = true;
        if (fell && rise > 0) break;
    }
    if (f >= points.size()) return double(points.back().y());
    while (f + 1 < points.size() && points[f + 1].y() > points[f].y()) ++f;
    return double(points[f].y());
}

/// Mean period of the body's x crossing `center` upwards (interpolated between frames).
double meanPeriod(const Trajectory& run, int body, double center) {
    const std::vector<Vec3> points = path(run, body);
    std::vector<double> crossings;
    for (std::size_t f = 1; f < points.size(); ++f) {
        const double before = double(points[f - 1].x()) - center, now = double(points[f].x()) - center;
        if (before < 0 && now >= 0) crossings.push_back((double(f - 1) + before / (before - now)) * run.dt);
    }
    if (crossings.size() < 2) return std::numeric_limits<double>::quiet_NaN();
    return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

Vec3 momentum(const World& world) {
    Vec3 total = Vec3::Zero();
    for (int body : dynamicBodies(world)) total += world.motionOf(body)->mass * world.motionOf(body)->linearVelocity;
    return total;
}

/// The first time after which the kinetic energy of translation (from the frames' moves) stays
/// below `fraction` of the starting energy; the run's length when it never does.
double timeToRest(const Trajectory& run, double fraction) {
    const double threshold = fraction * std::abs(computeEnergy(run.start).total());
    const std::vector<int> bodies = dynamicBodies(run.start);
    double restsFrom = 0;
    for (std::size_t f = 1; f < run.poses.size(); ++f) {
        double kinetic = 0;
        for (int body : bodies) {
            const Vec3 move = centreOfMass(run.start, body, run.poses[f][body]) - centreOfMass(run.start, body, run.poses[f - 1][body]);
            kinetic += 0.5 * double(run.start.motionOf(body)->mass) * double(move.squaredNorm()) / (run.dt * run.dt);
        }
        if (kinetic > threshold) restsFrom = double(f) * run.dt;
    }
    return restsFrom;
}

}  // namespace

void checkBodiesExist(const Sidecar& sidecar, const World& world, const std::string& source) {
    for (std::size_t i = 0; i < sidecar.checks.size(); ++i) {
        const Check& check = sidecar.checks[i];
        if (check.body.empty()) continue;
        const int body = world.findBody(check.body);
        if (body < 0 || world.bodies[body].type != BodyType::Dynamic)
            throw SidecarError(source + ": checks[" + std::to_string(i) + "].body: \"" + check.body +
                               "\" is not a dynamic body of scene \"" + world.name + "\"");
    }
}

double measureError(const Check& check, const Trajectory& run) {
    const int body = check.body.empty() ? -1 : run.start.findBody(check.body);
    const std::string& m = check.metric;
    if (m == "closed_form_position") return projectileError(run, body);
    if (m == "closed_form_rotation") return spinError(run, body);
    if (m == "bounce_apex") return std::abs(bounceApex(run, body) - check.expected);
    if (m == "final_speed") return std::abs(double(run.end.motionOf(body)->linearVelocity.norm()) - check.expected);
    if (m == "displacement") {
        const std::vector<Vec3> points = path(run, body);
        return std::abs(double((points.back() - points.front()).norm()) - check.expected);
    }
    if (m == "period") {
        const double period = meanPeriod(run, body, check.center);
        return std::isnan(period) ? std::abs(check.expected) : std::abs(period - check.expected);  // no swing: all of it wrong
    }
    if (m == "max_distance") {
        double worst = 0;
        for (const std::vector<Transform>& frame : run.poses)
            worst = std::max(worst, double((frame[body].apply(check.point) - check.to).norm()) - check.expected);
        return worst;
    }
    if (m == "max_coordinate") {
        double highest = -std::numeric_limits<double>::max();
        for (const Vec3& point : path(run, body)) highest = std::max(highest, double(point[check.axis]));
        return std::max(0.0, highest - check.limit);
    }
    if (m == "drift" || m == "sag") {
        double worst = 0;
        for (int dynamic : dynamicBodies(run.start)) {
            const Vec3 move = centreOfMass(run.start, dynamic, run.poses.back()[dynamic]) -
                              centreOfMass(run.start, dynamic, run.poses.front()[dynamic]);
            worst = std::max(worst, m == "drift" ? std::hypot(double(move.x()), double(move.z())) : -double(move.y()));
        }
        return worst;
    }
    if (m == "momentum") return double((momentum(run.end) - momentum(run.start)).norm());
    const double before = computeEnergy(run.start).total(), after = computeEnergy(run.end).total();
    if (m == "energy_change") return std::abs(after - before) / std::abs(before);
    if (m == "energy_gain") return std::max(0.0, after - before) / std::abs(before);
    if (m == "penetration") return run.finalPenetration < 0 ? std::numeric_limits<double>::quiet_NaN() : run.finalPenetration;
    if (m == "time_to_rest") return timeToRest(run, check.kineticFraction);
    throw SidecarError("metric \"" + m + "\" has no measurement (a bug: metricKeys() and measureError() disagree)");
}

Score scoreRun(const Sidecar& sidecar, const Trajectory& run) {
    Score score;
    for (std::size_t i = 0; i < sidecar.checks.size(); ++i) {
        const double error = measureError(sidecar.checks[i], run);
        score.errors.push_back(error);
        // A check the run could not measure cannot be said to pass.
        const double ratio = std::isnan(error) ? std::numeric_limits<double>::infinity() : error / sidecar.checks[i].tolerance;
        if (i == 0 || ratio > score.worst) {
            score.worst = ratio;
            score.worstCheck = i;
        }
    }
    return score;
}

}  // namespace stepwise::engine_bench
