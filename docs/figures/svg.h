#pragma once
// A few lines of SVG for the course's figures: a canvas with one or more viewports that map
// engine coordinates (x right, y up) to pixels. Plain text out, nothing to install.

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace figures {

struct Point2 {
    double x = 0, y = 0;
};

/// A rectangle of the canvas showing the engine's plane around `center` at `pixelsPerMetre`.
struct Viewport {
    double left = 0, top = 0, width = 400, height = 300;
    Point2 center;
    double pixelsPerMetre = 100;

    Point2 map(Point2 p) const {
        return {left + width / 2 + (p.x - center.x) * pixelsPerMetre,
                top + height / 2 - (p.y - center.y) * pixelsPerMetre};
    }
};

class Svg {
public:
    Svg(double width, double height) : width_(width), height_(height) {}

    void line(const Viewport& view, Point2 a, Point2 b, const std::string& style) {
        const Point2 p = view.map(a), q = view.map(b);
        body_ << "<line x1='" << p.x << "' y1='" << p.y << "' x2='" << q.x << "' y2='" << q.y << "' style='"
              << style << "'/>\n";
    }
    void polygon(const Viewport& view, const std::vector<Point2>& points, const std::string& style) {
        shape("polygon", view, points, style);
    }
    void polyline(const Viewport& view, const std::vector<Point2>& points, const std::string& style) {
        shape("polyline", view, points, "fill:none;" + style);
    }
    void dot(const Viewport& view, Point2 at, double radius, const std::string& fill) {
        const Point2 p = view.map(at);
        body_ << "<circle cx='" << p.x << "' cy='" << p.y << "' r='" << radius << "' style='fill:" << fill
              << "'/>\n";
    }
    void circle(const Viewport& view, Point2 at, double metres, const std::string& style) {
        const Point2 p = view.map(at);
        body_ << "<circle cx='" << p.x << "' cy='" << p.y << "' r='" << metres * view.pixelsPerMetre
              << "' style='" << style << "'/>\n";
    }
    void rect(double x, double y, double w, double h, const std::string& fill) {  // in pixels
        body_ << "<rect x='" << x << "' y='" << y << "' width='" << w << "' height='" << h << "' style='fill:"
              << fill << "'/>\n";
    }
    /// An arrow from a to b with a small head, in the given colour.
    void arrow(const Viewport& view, Point2 a, Point2 b, const std::string& colour, double width = 2) {
        const Point2 p = view.map(a), q = view.map(b);
        body_ << "<line x1='" << p.x << "' y1='" << p.y << "' x2='" << q.x << "' y2='" << q.y << "' style='stroke:"
              << colour << ";stroke-width:" << width << "' marker-end='url(#head-" << marker(colour) << ")'/>\n";
    }
    void text(const Viewport& view, Point2 at, const std::string& label, const std::string& style = "") {
        textAt(view.map(at), label, style);
    }
    void textAt(Point2 p, const std::string& label, const std::string& style = "") {
        body_ << "<text x='" << p.x << "' y='" << p.y << "' style='font:14px sans-serif;" << style << "'>";
        for (char c : label) {
            if (c == '<') body_ << "&lt;";
            else if (c == '>') body_ << "&gt;";
            else if (c == '&') body_ << "&amp;";
            else body_ << c;
        }
        body_ << "</text>\n";
    }
    /// A cross marking the origin.
    void origin(const Viewport& view, Point2 at = {}) {
        const Point2 p = view.map(at);
        body_ << "<path d='M" << p.x - 6 << ',' << p.y << "h12M" << p.x << ',' << p.y - 6
              << "v12' style='stroke:#000;stroke-width:2'/>\n";
    }

    bool save(const std::string& path) const {
        std::ostringstream out;
        out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width_ << "' height='" << height_
            << "' viewBox='0 0 " << width_ << ' ' << height_ << "'>\n<defs>\n";
        for (std::size_t i = 0; i < markers_.size(); ++i)
            out << "<marker id='head-" << i << "' viewBox='0 0 10 10' refX='9' refY='5' markerWidth='12' "
                << "markerHeight='12' markerUnits='userSpaceOnUse' orient='auto-start-reverse'><path d='M0,0L10,5L0,10z' style='fill:"
                << markers_[i] << "'/></marker>\n";
        out << "</defs>\n<rect width='100%' height='100%' style='fill:#fff'/>\n" << body_.str() << "</svg>\n";
        std::FILE* file = std::fopen(path.c_str(), "w");
        if (!file) return false;
        const std::string text = out.str();
        const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
        return std::fclose(file) == 0 && written;
    }

private:
    void shape(const char* tag, const Viewport& view, const std::vector<Point2>& points, const std::string& style) {
        body_ << '<' << tag << " points='";
        for (const Point2& point : points) {
            const Point2 p = view.map(point);
            body_ << p.x << ',' << p.y << ' ';
        }
        body_ << "' style='" << style << "'/>\n";
    }
    std::size_t marker(const std::string& colour) {
        for (std::size_t i = 0; i < markers_.size(); ++i)
            if (markers_[i] == colour) return i;
        markers_.push_back(colour);
        return markers_.size() - 1;
    }

    double width_, height_;
    std::ostringstream body_;
    std::vector<std::string> markers_;
};

}  // namespace figures
