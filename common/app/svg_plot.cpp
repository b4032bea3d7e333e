#include "app/svg_plot.h"

#include "app/bench_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace stepwise {

namespace {

// Text metrics for the 12 px sans-serif font the SVGs use, generous so nothing is cut off.
constexpr double kCharWidth = 7.2;
constexpr double kLineHeight = 17;

// Maps data to the plot area, on a log or linear scale.
struct Axis {
    double low = 0, high = 1;     // in transformed units (log10 on a log axis)
    bool log = false;
    std::vector<double> ticks;    // data values
    double pixelLow = 0, pixelHigh = 1;

    double transform(double value) const { return log ? std::log10(value) : value; }
    double toPixel(double value) const {
        const double t = (transform(value) - low) / (high - low);
        return pixelLow + t * (pixelHigh - pixelLow);
    }
};

bool usable(double value, bool logScale) { return std::isfinite(value) && (!logScale || value > 0); }

// Every value a series puts on this axis: its points and their whiskers.
void collect(const PlotSeries& series, bool isX, bool logX, bool logY, std::vector<double>& values) {
    for (size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
        if (!usable(series.x[i], logX) || !usable(series.y[i], logY)) continue;
        values.push_back(isX ? series.x[i] : series.y[i]);
        const std::vector<double>& low = isX ? series.xLow : series.yLow;
        const std::vector<double>& high = isX ? series.xHigh : series.yHigh;
        if (i < low.size()) values.push_back(low[i]);
        if (i < high.size()) values.push_back(high[i]);
    }
}

Axis fitAxis(const PlotSpec& spec, bool isX, double pixelLow, double pixelHigh) {
    Axis axis;
    axis.log = isX ? spec.logX : spec.logY;
    axis.pixelLow = pixelLow;
    axis.pixelHigh = pixelHigh;
    std::vector<double> values;
    for (const PlotSeries& series : spec.series) collect(series, isX, spec.logX, spec.logY, values);
    double low = INFINITY, high = -INFINITY;
    for (double value : values)
        if (usable(value, axis.log)) low = std::min(low, axis.transform(value)), high = std::max(high, axis.transform(value));
    if (!(low <= high)) low = 0, high = 1;
    if (axis.log) {
        low = std::floor(low), high = std::ceil(high);
        if (high - low < 1) high = low + 1;
        // Every decade when they fit, else every second or third one.
        const int stride = high - low > 12 ? 3 : high - low > 7 ? 2 : 1;
        for (double e = low; e <= high + 1e-9; e += stride) axis.ticks.push_back(std::pow(10.0, e));
    } else {
        axis.ticks = linearTicks(low, high, isX ? spec.integerX : spec.integerY);
        low = std::min(low, axis.ticks.front()), high = std::max(high, axis.ticks.back());
    }
    axis.low = low, axis.high = high;
    return axis;
}

// "0.001", "250", "1e-06" -> "1e-6": short labels without a plus sign or leading zeros.
std::string tickLabel(double value) {
    if (value == 0) return "0";
    const double magnitude = std::abs(value);
    if (magnitude >= 1e-3 && magnitude < 1e5) return formatNumber(value, 6);
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    std::string label = text;
    const size_t e = label.find('e');
    if (e == std::string::npos) return label;
    std::string mantissa = label.substr(0, e), exponent = label.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    return mantissa + "e" + (negative ? "-" : "") + exponent;
}

/// A count's label, a whole number with thousands separators: 100000 -> "100,000".
std::string countLabel(double value) {
    if (std::abs(value) < 1) return tickLabel(value);
    std::string digits = std::to_string(static_cast<long long>(std::llround(value)));
    const std::ptrdiff_t sign = digits[0] == '-' ? 1 : 0;
    for (std::ptrdiff_t at = static_cast<std::ptrdiff_t>(digits.size()) - 3; at > sign; at -= 3)
        digits.insert(static_cast<std::size_t>(at), ",");
    return digits;
}

std::string escapeXml(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
}

// Greedy word wrap.
std::vector<std::string> wrap(const std::string& text, size_t width) {
    std::vector<std::string> lines;
    std::istringstream words(text);
    std::string word, line;
    while (words >> word) {
        if (!line.empty() && line.size() + 1 + word.size() > width) lines.push_back(line), line.clear();
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

void writeFile(const std::string& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot write '" + path + "'");
    file << text;
    if (!file) throw std::runtime_error("cannot write '" + path + "'");
}

const char* kSeriesColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
                               "#7f7f7f", "#bcbd22"};

}  // namespace

std::vector<double> linearTicks(double low, double high, bool integer) {
    if (!(high > low)) high = low + 1;
    const double raw = (high - low) / 5;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    double step = decade * 10;
    for (double factor : {1.0, 2.0, 5.0})
        if (decade * factor >= raw) {
            step = decade * factor;
            break;
        }
    if (integer) step = std::max(1.0, std::round(step));
    std::vector<double> ticks;
    const double first = std::floor(low / step + 1e-9) * step;
    for (double tick = first;; tick += step) {
        ticks.push_back(std::abs(tick) < 1e-9 * step ? 0 : tick);
        if (tick >= high - 1e-6 * step) break;  // round-off in `high` adds no empty step
    }
    return ticks;
}

void writeSvgPlot(const std::string& path, const PlotSpec& spec) {
    size_t longestTitle = 0;
    for (const PlotSeries& series : spec.series) longestTitle = std::max(longestTitle, series.title.size());
    const double left = 80, plotWidth = 440, top = 40, plotHeight = 380;
    const double right = std::max(120.0, 40 + kCharWidth * double(longestTitle));
    const double width = left + plotWidth + right;
    const std::vector<std::string> caption = wrap(spec.caption, size_t((width - 20) / kCharWidth));
    const double axisBottom = top + plotHeight, plotRight = left + plotWidth;
    const double height = axisBottom + 52 + kLineHeight * double(caption.size()) + (caption.empty() ? 0 : 8);
    const Axis xAxis = fitAxis(spec, true, left, plotRight);
    const Axis yAxis = fitAxis(spec, false, axisBottom, top);

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << (left + plotRight) / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
        << escapeXml(spec.title) << "</text>\n";
    for (double value : xAxis.ticks) {
        const double x = xAxis.toPixel(value);
        svg << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << axisBottom
            << "\" stroke=\"#ddd\"/>\n<text x=\"" << x << "\" y=\"" << axisBottom + 16 << "\" text-anchor=\"middle\">"
            << (spec.integerX ? countLabel(value) : tickLabel(value)) << "</text>\n";
    }
    for (double value : yAxis.ticks) {
        const double y = yAxis.toPixel(value);
        svg << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << plotRight << "\" y2=\"" << y
            << "\" stroke=\"#ddd\"/>\n<text x=\"" << left - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
            << (spec.integerY ? countLabel(value) : tickLabel(value)) << "</text>\n";
    }
    svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << plotWidth << "\" height=\"" << plotHeight
        << "\" fill=\"none\" stroke=\"black\"/>\n"
        << "<text x=\"" << (left + plotRight) / 2 << "\" y=\"" << axisBottom + 38 << "\" text-anchor=\"middle\">"
        << escapeXml(spec.xLabel) << "</text>\n"
        << "<text transform=\"translate(18," << (top + axisBottom) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
        << escapeXml(spec.yLabel) << "</text>\n";
    for (size_t s = 0; s < spec.series.size(); ++s) {
        const PlotSeries& series = spec.series[s];
        const char* color = kSeriesColors[s % (sizeof kSeriesColors / sizeof *kSeriesColors)];
        std::ostringstream points;
        const auto whisker = [&](double x1, double y1, double x2, double y2) {
            svg << "<line x1=\"" << x1 << "\" y1=\"" << y1 << "\" x2=\"" << x2 << "\" y2=\"" << y2 << "\" stroke=\""
                << color << "\" stroke-width=\"1.2\"/>\n";
        };
        for (size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
            if (!usable(series.x[i], spec.logX) || !usable(series.y[i], spec.logY)) continue;
            const double x = xAxis.toPixel(series.x[i]), y = yAxis.toPixel(series.y[i]);
            points << x << "," << y << " ";
            if (!series.lineOnly)
                svg << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"3\" fill=\"" << color << "\"/>\n";
            if (i < series.xLow.size() && i < series.xHigh.size() && usable(series.xLow[i], spec.logX) &&
                usable(series.xHigh[i], spec.logX)) {
                const double x1 = xAxis.toPixel(series.xLow[i]), x2 = xAxis.toPixel(series.xHigh[i]);
                whisker(x1, y, x2, y), whisker(x1, y - 4, x1, y + 4), whisker(x2, y - 4, x2, y + 4);
            }
            if (i < series.yLow.size() && i < series.yHigh.size() && usable(series.yLow[i], spec.logY) &&
                usable(series.yHigh[i], spec.logY)) {
                const double y1 = yAxis.toPixel(series.yLow[i]), y2 = yAxis.toPixel(series.yHigh[i]);
                whisker(x, y1, x, y2), whisker(x - 4, y1, x + 4, y1), whisker(x - 4, y2, x + 4, y2);
            }
        }
        if (!series.markersOnly)
            svg << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.5\""
                << (series.dashed ? " stroke-dasharray=\"6,4\"" : "") << " points=\"" << points.str() << "\"/>\n";
        const double legendY = top + 10 + 18 * static_cast<double>(s);
        svg << "<rect x=\"" << plotRight + 12 << "\" y=\"" << legendY - 9 << "\" width=\"12\" height=\"12\" fill=\""
            << color << "\"/>\n<text x=\"" << plotRight + 30 << "\" y=\"" << legendY + 1 << "\">"
            << escapeXml(series.title) << "</text>\n";
    }
    for (size_t i = 0; i < caption.size(); ++i)
        svg << "<text x=\"10\" y=\"" << axisBottom + 64 + kLineHeight * double(i) << "\" fill=\"#333\">"
            << escapeXml(caption[i]) << "</text>\n";
    svg << "</svg>\n";
    writeFile(path, svg.str());
}

void writeSvgTables(const std::string& path, const std::vector<FigureTable>& figures) {
    const double margin = 10;
    std::ostringstream body;
    double y = margin + 12, width = 0;
    auto textAt = [&](double x, const std::string& text, bool bold) {
        body << "<text x=\"" << x << "\" y=\"" << y << "\"" << (bold ? " font-weight=\"bold\"" : "") << ">"
             << escapeXml(text) << "</text>\n";
    };
    for (const FigureTable& figure : figures) {
        for (const std::string& note : figure.notes) {
            textAt(margin, note, false);
            width = std::max(width, 2 * margin + kCharWidth * double(note.size()));
            y += kLineHeight;
        }
        const CsvTable& table = *figure.table;
        std::vector<double> columnX;
        double x = margin;
        for (size_t c = 0; c < table.columns().size(); ++c) {
            size_t widest = table.columns()[c].size();
            for (const auto& row : table.rows()) widest = std::max(widest, c < row.size() ? row[c].size() : 0);
            columnX.push_back(x);
            x += kCharWidth * double(widest + 2);
        }
        width = std::max(width, x + margin);
        for (size_t c = 0; c < table.columns().size(); ++c) textAt(columnX[c], table.columns()[c], true);
        y += kLineHeight;
        for (const auto& row : table.rows()) {
            for (size_t c = 0; c < row.size() && c < columnX.size(); ++c) textAt(columnX[c], row[c], false);
            y += kLineHeight;
        }
        y += kLineHeight;
    }
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << y
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << body.str() << "</svg>\n";
    writeFile(path, svg.str());
}

}  // namespace stepwise
