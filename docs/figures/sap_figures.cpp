// Figures for chapter 5, computed by the engine's own sweep and prune: why the axis matters.
#include "figures.h"

#include "05_sap/sweep_and_prune.h"

#include <cstdio>
#include <iterator>

namespace figures {

using namespace stepwise;

bool drawSweepAxisChoice(const std::string& path) {
    // Ten boxes resting on the ground, seen from the side (x right, y up). Each box's interval
    // on x is drawn below the ground and its interval on y to the left. The engine's variance
    // picks the axis, and its sweep counts the pairs it would look at along x and along y.
    // Neighbours alternate between two rows in z (out of the page), so boxes whose intervals
    // overlap on x are still apart: looked at, but not pairs.
    const struct {
        double x, halfWidth, halfHeight;
    } layout[] = {{-4.1, 0.35, 0.35}, {-3.5, 0.3, 0.5},  {-2.7, 0.45, 0.3}, {-1.9, 0.3, 0.3},  {-1.1, 0.4, 0.45},
                  {-0.3, 0.35, 0.25}, {0.5, 0.3, 0.55},  {1.3, 0.45, 0.35}, {2.3, 0.3, 0.3},   {3.0, 0.35, 0.45}};
    std::vector<Aabb> bounds;
    for (std::size_t i = 0; i < std::size(layout); ++i) {
        const auto& body = layout[i];
        const double z = i % 2 == 0 ? -1.0 : 1.0;
        Aabb box;
        box.min = Vec3(Real(body.x - body.halfWidth), 0, Real(z - 0.3));
        box.max = Vec3(Real(body.x + body.halfWidth), Real(2 * body.halfHeight), Real(z + 0.3));
        bounds.push_back(box);
    }
    const std::vector<char> dynamic(bounds.size(), 1);
    const Vec3 variance = centreVariance(bounds);
    const int axis = chooseSweepAxis(variance, -1);
    long looked[2] = {0, 0};
    for (int along = 0; along < 2; ++along) {
        std::vector<SweepEndpoint> ends;
        std::vector<BodyPair> pairs;
        makeEndpoints(bounds, along, ends);
        fullSortEndpoints(ends);
        looked[along] = sweepEndpoints(ends, bounds, dynamic, along, pairs);
    }

    Svg svg(820, 400);
    const Viewport view{0, 40, 820, 360, {-0.35, 0.1}, 74};
    svg.polygon(view, {{-4.7, -0.12}, {4.9, -0.12}, {4.9, 0}, {-4.7, 0}}, "fill:#bbb");
    const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd"};
    const double xAxisY = -1.1, yAxisX = -5.6;
    svg.arrow(view, {-4.7, xAxisY}, {4.9, xAxisY}, "#333");
    svg.text(view, {4.2, xAxisY - 0.32}, "x");
    svg.arrow(view, {yAxisX, -0.3}, {yAxisX, 1.8}, "#333");
    svg.text(view, {yAxisX - 0.3, 1.75}, "y");
    for (std::size_t i = 0; i < bounds.size(); ++i) {
        const std::string colour = colours[i % 5];
        const Aabb& box = bounds[i];
        const double x0 = box.min.x(), x1 = box.max.x(), y0 = box.min.y(), y1 = box.max.y();
        svg.polygon(view, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, "fill:" + colour + ";fill-opacity:0.35;stroke:" + colour);
        const double lane = xAxisY + 0.2 + 0.14 * static_cast<double>(i % 3);
        svg.line(view, {x0, lane}, {x1, lane}, "stroke:" + colour + ";stroke-width:4");
        const double column = yAxisX + 0.15 + 0.07 * static_cast<double>(i);
        svg.line(view, {column, y0}, {column, y1}, "stroke:" + colour + ";stroke-width:3");
    }
    const long all = static_cast<long>(bounds.size() * (bounds.size() - 1) / 2);
    char label[240];
    std::snprintf(label, sizeof label, "along x the sweep looks at %ld of the %ld pairs, along y at %ld", looked[0],
                  all, looked[1]);
    svg.textAt({12, 22}, label, "fill:#333");
    std::snprintf(label, sizeof label, "variance of the centres: x %.2f m^2, y %.3f m^2, so the sweep runs along %c",
                  double(variance.x()), double(variance.y()), "xyz"[axis]);
    svg.textAt({12, 42}, label, "fill:#333");
    return svg.save(path);
}

}  // namespace figures
