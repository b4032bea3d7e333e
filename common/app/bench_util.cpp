#include "app/bench_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#if defined(__unix__) || defined(__APPLE__)
#include <time.h>
#endif

namespace stepwise {

double ThreadStopwatch::now() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec time{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &time);
    return static_cast<double>(time.tv_sec) + 1e-9 * static_cast<double>(time.tv_nsec);
#else
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
#endif
}

std::string formatNumber(double value, int significantDigits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", significantDigits, value);
    return buffer;
}

static std::ofstream openForWriting(const std::string& path) {
    std::ofstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot write '" + path + "'");
    return file;
}

void CsvTable::write(const std::string& path) const {
    std::ofstream file = openForWriting(path);
    auto writeRow = [&](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size(); ++i) file << (i ? "," : "") << cells[i];
        file << "\n";
    };
    writeRow(columns_);
    for (const auto& row : rows_) writeRow(row);
}

std::string CsvTable::toText() const {
    std::vector<size_t> widths(columns_.size(), 0);
    for (size_t i = 0; i < columns_.size(); ++i) widths[i] = columns_[i].size();
    for (const auto& row : rows_)
        for (size_t i = 0; i < row.size() && i < widths.size(); ++i) widths[i] = std::max(widths[i], row[i].size());
    std::ostringstream out;
    auto writeRow = [&](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size() && i < widths.size(); ++i)
            out << cells[i] << std::string(widths[i] - cells[i].size() + 2, ' ');
        out << "\n";
    };
    writeRow(columns_);
    for (const auto& row : rows_) writeRow(row);
    return out.str();
}

namespace {

// Maps data to the plot area, on a log or linear scale.
struct Axis {
    double low = 0, high = 1;
    bool log = false;
    double pixelLow = 0, pixelHigh = 1;

    double transform(double value) const { return log ? std::log10(value) : value; }
    double toPixel(double value) const {
        const double t = (transform(value) - low) / (high - low);
        return pixelLow + t * (pixelHigh - pixelLow);
    }
};

bool usable(double value, bool logScale) { return std::isfinite(value) && (!logScale || value > 0); }

Axis fitAxis(const PlotSpec& spec, bool isX, double pixelLow, double pixelHigh) {
    Axis axis;
    axis.log = isX ? spec.logX : spec.logY;
    axis.pixelLow = pixelLow;
    axis.pixelHigh = pixelHigh;
    double low = INFINITY, high = -INFINITY;
    for (const PlotSeries& series : spec.series)
        for (size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
            if (!usable(series.x[i], spec.logX) || !usable(series.y[i], spec.logY)) continue;
            const double value = axis.transform(isX ? series.x[i] : series.y[i]);
            low = std::min(low, value), high = std::max(high, value);
        }
    if (!(low <= high)) low = 0, high = 1;
    if (axis.log) low = std::floor(low), high = std::ceil(high);
    if (high - low < 1e-12) high = low + 1;
    if (!axis.log) {
        const double pad = 0.05 * (high - low);
        low -= pad, high += pad;
    }
    axis.low = low, axis.high = high;
    return axis;
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

/// A whole number with thousands separators: 100000 -> "100,000".
std::string countLabel(double value) {
    std::string digits = std::to_string(static_cast<long long>(std::llround(value)));
    const std::size_t sign = digits[0] == '-' ? 1 : 0;
    for (std::ptrdiff_t at = static_cast<std::ptrdiff_t>(digits.size()) - 3; at > static_cast<std::ptrdiff_t>(sign); at -= 3)
        digits.insert(static_cast<std::size_t>(at), ",");
    return digits;
}

const char* kSeriesColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

}  // namespace

void writeSvgPlot(const std::string& path, const PlotSpec& spec) {
    const double width = 720, height = 480, left = 80, right = 200, top = 40, bottom = 60;
    const Axis xAxis = fitAxis(spec, true, left, width - right);
    const Axis yAxis = fitAxis(spec, false, height - bottom, top);
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << (left + width - right) / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
        << escapeXml(spec.title) << "</text>\n";
    // Grid and tick labels: decades on log axes, five steps on linear ones.
    auto ticks = [](const Axis& axis) {
        std::vector<double> values;
        if (axis.log) {
            for (double e = axis.low; e <= axis.high + 1e-9; e += 1) values.push_back(std::pow(10.0, e));
        } else {
            for (int i = 0; i <= 5; ++i) values.push_back(axis.low + (axis.high - axis.low) * i / 5);
        }
        return values;
    };
    for (double value : ticks(xAxis)) {
        const double x = xAxis.toPixel(value);
        svg << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << height - bottom
            << "\" stroke=\"#ddd\"/>\n<text x=\"" << x << "\" y=\"" << height - bottom + 16
            << "\" text-anchor=\"middle\">" << (spec.xCounts ? countLabel(value) : formatNumber(value, 3)) << "</text>\n";
    }
    for (double value : ticks(yAxis)) {
        const double y = yAxis.toPixel(value);
        svg << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << width - right << "\" y2=\"" << y
            << "\" stroke=\"#ddd\"/>\n<text x=\"" << left - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
            << formatNumber(value, 3) << "</text>\n";
    }
    svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << width - right - left << "\" height=\""
        << height - bottom - top << "\" fill=\"none\" stroke=\"black\"/>\n"
        << "<text x=\"" << (left + width - right) / 2 << "\" y=\"" << height - 18 << "\" text-anchor=\"middle\">"
        << escapeXml(spec.xLabel) << "</text>\n"
        << "<text transform=\"translate(18," << (top + height - bottom) / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << escapeXml(spec.yLabel) << "</text>\n";
    for (size_t s = 0; s < spec.series.size(); ++s) {
        const PlotSeries& series = spec.series[s];
        const char* color = kSeriesColors[s % (sizeof kSeriesColors / sizeof *kSeriesColors)];
        std::ostringstream points;
        for (size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
            if (!usable(series.x[i], spec.logX) || !usable(series.y[i], spec.logY)) continue;
            const double x = xAxis.toPixel(series.x[i]), y = yAxis.toPixel(series.y[i]);
            points << x << "," << y << " ";
            svg << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"3\" fill=\"" << color << "\"/>\n";
        }
        if (!series.markersOnly)
            svg << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.5\" points=\"" << points.str()
                << "\"/>\n";
        const double legendY = top + 10 + 18 * static_cast<double>(s);
        svg << "<rect x=\"" << width - right + 12 << "\" y=\"" << legendY - 9 << "\" width=\"12\" height=\"12\" fill=\""
            << color << "\"/>\n<text x=\"" << width - right + 30 << "\" y=\"" << legendY + 1 << "\">"
            << escapeXml(series.title) << "</text>\n";
    }
    svg << "</svg>\n";
    std::ofstream file = openForWriting(path);
    file << svg.str();
}

}  // namespace stepwise
