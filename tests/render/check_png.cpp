// Checks a demo screenshot for content, natively (no wine): the image is not blank, at least
// one body and (when the scene has one) the ground show in their colours where the camera
// puts them, the ImGui panel (and the debugger, when open) is drawn, the box the camera was
// framed from (bodies and the scene's overlay) lies on screen between them, and every debug
// view's group of marks ("mark contact ...": red cubes at the contact points, "mark normal",
// "mark epa", ...) shows its colour at a quarter of its places at least. The demo writes IMAGE.txt
// next to the image with those screen places (renderer_dx12/expectations.cpp), computed from
// the world and the camera, never from the image.
//   check_png IMAGE.png [EXPECTATIONS.txt]     screenshot check
//   check_png --window SCREEN.xwd             the swap-chain test: a window with the shell shows
// Exit 0 when every check passes, 1 with one line per failed check, 2 on bad input.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb;
    const uint8_t* at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};

bool loadPng(const std::string& path, Image& image) {
    int channels = 0;
    uint8_t* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
    if (!data) return false;
    image.rgb.assign(data, data + static_cast<size_t>(image.width) * image.height * 3);
    stbi_image_free(data);
    return true;
}

uint32_t bigEndian(const std::vector<uint8_t>& bytes, size_t offset) {
    return (uint32_t(bytes[offset]) << 24) | (uint32_t(bytes[offset + 1]) << 16) | (uint32_t(bytes[offset + 2]) << 8) |
           uint32_t(bytes[offset + 3]);
}

/// X Window Dump (xwd -root) of a 24-bit TrueColor screen: 32 bits per pixel.
bool loadXwd(const std::string& path, Image& image) {
    std::ifstream in(path, std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < 100) return false;
    const uint32_t headerSize = bigEndian(bytes, 0), width = bigEndian(bytes, 16), height = bigEndian(bytes, 20);
    const uint32_t byteOrder = bigEndian(bytes, 28), bitsPerPixel = bigEndian(bytes, 44), bytesPerLine = bigEndian(bytes, 48);
    const uint32_t colors = bigEndian(bytes, 76);
    const size_t pixels = size_t(headerSize) + size_t(colors) * 12;
    // Xvfb's depth-24 screens store 4 bytes a pixel while the header may say 24 bits.
    const uint32_t bytesPerPixel = width ? bytesPerLine / width : 0;
    if ((bitsPerPixel != 24 && bitsPerPixel != 32) || (bytesPerPixel != 3 && bytesPerPixel != 4) || width == 0 || height == 0 || width > 16384 || height > 16384 ||
        pixels + size_t(bytesPerLine) * height > bytes.size()) {
        return false;
    }
    image.width = int(width);
    image.height = int(height);
    image.rgb.resize(size_t(width) * height * 3);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const uint8_t* p = &bytes[pixels + size_t(y) * bytesPerLine + size_t(x) * bytesPerPixel];
            uint8_t* out = &image.rgb[(size_t(y) * width + x) * 3];
            const uint8_t* msb = bytesPerPixel == 4 ? p + 1 : p;
            if (byteOrder == 0) {  // LSBFirst: B G R (X)
                out[0] = p[2], out[1] = p[1], out[2] = p[0];
            } else {  // MSBFirst: (X) R G B
                out[0] = msb[0], out[1] = msb[1], out[2] = msb[2];
            }
        }
    }
    return true;
}

/// Shaded pixels are the flat colour times a lighting factor: find that factor, then require
/// it in [minShade, 1.15] and the rest of the pixel to match within a tolerance.
bool matches(const uint8_t* pixel, const int expected[3], double minShade) {
    double dotPe = 0, dotEe = 0;
    for (int c = 0; c < 3; ++c) {
        dotPe += double(pixel[c]) * expected[c];
        dotEe += double(expected[c]) * expected[c];
    }
    if (dotEe <= 0) return false;
    const double shade = dotPe / dotEe;
    if (shade < minShade || shade > 1.15) return false;
    for (int c = 0; c < 3; ++c)
        if (std::abs(double(pixel[c]) - shade * expected[c]) > 28) return false;
    return true;
}

bool matchesNear(const Image& image, int x, int y, const int expected[3], double minShade, int radius) {
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int px = x + dx, py = y + dy;
            if (px >= 0 && py >= 0 && px < image.width && py < image.height && matches(image.at(px, py), expected, minShade))
                return true;
        }
    return false;
}

/// Not blank: many distinct colours, and a good share of pixels unlike the top-right corner.
int checkNotBlank(const Image& image, std::vector<std::string>& failures) {
    std::set<uint32_t> distinct;
    const uint8_t* corner = image.at(image.width - 1, 0);
    size_t different = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const uint8_t* p = image.at(x, y);
            distinct.insert((uint32_t(p[0] >> 3) << 10) | (uint32_t(p[1] >> 3) << 5) | uint32_t(p[2] >> 3));
            if (std::abs(p[0] - corner[0]) + std::abs(p[1] - corner[1]) + std::abs(p[2] - corner[2]) > 24) ++different;
        }
    const double share = double(different) / (double(image.width) * image.height);
    if (distinct.size() < 40) failures.push_back("blank: only " + std::to_string(distinct.size()) + " distinct colours");
    if (share < 0.05) failures.push_back("blank: only " + std::to_string(int(share * 100)) + "% of pixels differ from the background");
    return static_cast<int>(distinct.size());
}

/// Dear ImGui's dark style: window background ~(15,15,15), title bar (41,74,122) when focused,
/// light text. `what` names the window in failures.
void checkPanel(const Image& image, int x0, int y0, int x1, int y1, bool focused, const std::string& what,
                std::vector<std::string>& failures) {
    x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
    size_t dark = 0, bright = 0, total = 0, title = 0, titleTotal = 0;
    const int titleBlue[3] = {41, 74, 122};
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const uint8_t* p = image.at(x, y);
            ++total;
            if (std::max({p[0], p[1], p[2]}) < 45) ++dark;
            if (std::min({p[0], p[1], p[2]}) > 170) ++bright;
            if (y >= y0 + 3 && y <= y0 + 12) {
                ++titleTotal;
                if (matches(p, titleBlue, 0.85)) ++title;
            }
        }
    if (total == 0) return failures.push_back(what + ": empty rectangle");
    if (dark < total * 4 / 10) failures.push_back(what + ": background not drawn (" + std::to_string(100 * dark / total) + "% dark)");
    if (bright < total / 200) failures.push_back(what + ": no text drawn");
    if (focused && (titleTotal == 0 || title < titleTotal / 2)) failures.push_back(what + ": no title bar");
}

int checkWindow(const std::string& path) {
    Image image;
    if (!loadXwd(path, image)) return std::cerr << "check_png: cannot read xwd '" << path << "'\n", 2;
    std::vector<std::string> failures;
    const int distinct = checkNotBlank(image, failures);
    // The shell's title bar somewhere on screen: a run of its blue in many pixels.
    const int titleBlue[3] = {41, 74, 122};
    size_t title = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) title += matches(image.at(x, y), titleBlue, 0.85) ? 1 : 0;
    if (title < 1500) failures.push_back("window: ImGui title bar not found (" + std::to_string(title) + " pixels)");
    for (const std::string& failure : failures) std::cout << "FAIL " << failure << '\n';
    std::cout << (failures.empty() ? "ok " : "failed ") << path << ": " << image.width << "x" << image.height << ", "
              << distinct << " colours, " << title << " title-bar pixels\n";
    return failures.empty() ? 0 : 1;
}

int checkScreenshot(const std::string& imagePath, const std::string& expectPath) {
    Image image;
    if (!loadPng(imagePath, image)) return std::cerr << "check_png: cannot read PNG '" << imagePath << "'\n", 2;
    std::ifstream expectations(expectPath);
    if (!expectations) return std::cerr << "check_png: cannot read '" << expectPath << "'\n", 2;

    std::vector<std::string> failures;
    const int distinct = checkNotBlank(image, failures);
    int bodies = 0, bodyHits = 0, grounds = 0, groundHits = 0;
    bool panel = false;
    float panelRight = 0, debuggerLeft = float(image.width);
    std::map<std::string, std::pair<int, int>> marks;   // group -> (places, places where seen)
    std::string line;
    while (std::getline(expectations, line)) {
        std::istringstream in(line);
        std::string kind, name;
        in >> kind;
        if (kind == "size") {
            int w = 0, h = 0;
            in >> w >> h;
            if (w != image.width || h != image.height) failures.push_back("size: image is not " + std::to_string(w) + "x" + std::to_string(h));
        } else if (kind == "panel") {
            float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
            in >> x0 >> y0 >> x1 >> y1;
            checkPanel(image, int(x0), int(y0), int(x1), int(y1), true, "panel", failures);
            panel = true;
            panelRight = x1;
        } else if (kind == "debugger") {
            float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
            in >> x0 >> y0 >> x1 >> y1;
            checkPanel(image, int(x0), int(y0), int(x1), int(y1), false, "debugger", failures);
            debuggerLeft = x0;
        } else if (kind == "framed") {
            // The box the camera was framed from must be on screen, right of the panel (the
            // panel line comes first); 2 px for rounding.
            std::string first;
            in >> first;
            if (first == "behind") {
                failures.push_back("framing: part of the framed box is behind the camera");
                continue;
            }
            float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
            std::istringstream(first) >> x0;
            in >> y0 >> x1 >> y1;
            if (!in || !std::isfinite(x0)) return std::cerr << "check_png: bad line '" << line << "'\n", 2;
            std::ostringstream where;
            where << "framed box spans x " << x0 << ".." << x1 << ", y " << y0 << ".." << y1;
            if (x0 < panelRight - 2) failures.push_back("framing: " + where.str() + ", under the panel (right edge " + std::to_string(int(panelRight)) + ")");
            if (x1 > debuggerLeft + 2)
                failures.push_back("framing: " + where.str() + ", under the debugger (left edge " + std::to_string(int(debuggerLeft)) + ")");
            if (x0 < -2 || y0 < -2 || x1 > image.width + 2 || y1 > image.height + 2)
                failures.push_back("framing: " + where.str() + ", not all on screen");
        } else if (kind == "body" || kind == "ground") {
            int x = 0, y = 0, color[3] = {0, 0, 0};
            double minShade = 0;
            in >> name >> x >> y >> color[0] >> color[1] >> color[2] >> minShade;
            if (!in) return std::cerr << "check_png: bad line '" << line << "'\n", 2;
            const bool hit = matchesNear(image, x, y, color, minShade, 3);
            (kind == "body" ? bodies : grounds) += 1;
            (kind == "body" ? bodyHits : groundHits) += hit ? 1 : 0;
            if (!hit) std::cout << "  " << kind << " '" << name << "' not seen at (" << x << ", " << y << ")\n";
        } else if (kind == "mark") {
            // A debug view's mark: small (a 6 cm cube, a 2-pixel line), so it is looked for
            // within 4 pixels; some places of a group may be hidden behind a body.
            std::string group;
            int x = 0, y = 0, color[3] = {0, 0, 0};
            double minShade = 0;
            in >> group >> name >> x >> y >> color[0] >> color[1] >> color[2] >> minShade;
            if (!in) return std::cerr << "check_png: bad line '" << line << "'\n", 2;
            const bool hit = matchesNear(image, x, y, color, minShade, 4);
            marks[group].first += 1;
            marks[group].second += hit ? 1 : 0;
        }
    }
    for (const auto& [group, counts] : marks) {
        std::cout << "  view '" << group << "': seen at " << counts.second << " of " << counts.first << " places\n";
        // A quarter of the places at least: enough that a colour some body happens to share
        // near a few of them (cyan bounds beside a cyan box) does not pass for the view.
        const int needed = std::max(1, (counts.first + 3) / 4);
        if (counts.second < needed)
            failures.push_back("view '" + group + "': its colour shows at " + std::to_string(counts.second) + " of its " +
                               std::to_string(counts.first) + " places (at least " + std::to_string(needed) + " wanted)");
    }
    if (!panel) failures.push_back("panel: the demo reported no ImGui panel");
    // A view of wireframes only (the selection and what it touches) leaves no solid body: its
    // marks stand in for them.
    if (bodies == 0 && marks.empty()) failures.push_back("bodies: no body in view per the camera");
    else if (bodies > 0 && bodyHits == 0) failures.push_back("bodies: none of " + std::to_string(bodies) + " bodies shows its colour where the camera puts it");
    if (grounds > 0 && groundHits == 0) failures.push_back("ground: not seen at any of " + std::to_string(grounds) + " places");
    for (const std::string& failure : failures) std::cout << "FAIL " << failure << '\n';
    std::cout << (failures.empty() ? "ok " : "failed ") << imagePath << ": " << distinct << " colours, bodies "
              << bodyHits << "/" << bodies << ", ground " << groundHits << "/" << grounds << '\n';
    return failures.empty() ? 0 : 1;
}

/// The checker must fail on a blank image and pass on one that has what the file promises.
int selfTest(const std::string& folder) {
    const int w = 320, h = 200;
    std::vector<uint8_t> rgb(size_t(w) * h * 3);
    auto fill = [&](int x0, int y0, int x1, int y1, uint8_t r, uint8_t g, uint8_t b) {
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                uint8_t* p = &rgb[(size_t(y) * w + x) * 3];
                p[0] = r, p[1] = g, p[2] = b;
            }
    };
    const std::string expect = "size 320 200\npanel 4 4 100 120\nframed 110 20 300 190\nbody cube 200 60 235 188 69 0.25\n"
                               "ground floor 200 170 140 140 148 0.55\nmark contact p0 262 152 230 51 51 0.3\n"
                               "mark contact p1 150 190 230 51 51 0.3\n";
    fill(0, 0, w, h, 41, 46, 54);
    const std::string blank = folder + "/blank.png";
    if (!stbi_write_png(blank.c_str(), w, h, 3, rgb.data(), w * 3)) return 2;
    std::ofstream(blank + ".txt") << expect;
    // A plausible frame: a shaded sky, a gradient floor, a shaded box, a panel with title bar and text rows.
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < w; x += 4) fill(x, y, x + 4, y + 1, uint8_t(41 + x / 4), 46, uint8_t(54 + y / 2));
    for (int y = 100; y < h; ++y) fill(0, y, w, y + 1, uint8_t(100 + (y - 100) / 3), uint8_t(100 + (y - 100) / 3), uint8_t(106 + (y - 100) / 3));
    fill(180, 40, 230, 90, 200, 160, 59);
    fill(259, 149, 265, 155, 150, 35, 35);   // a contact cube, on its shaded side
    fill(4, 4, 100, 120, 15, 15, 15);
    fill(4, 4, 100, 18, 41, 74, 122);
    for (int row = 30; row < 110; row += 12) fill(10, row, 90, row + 2, 230, 230, 230);
    const std::string good = folder + "/good.png";
    if (!stbi_write_png(good.c_str(), w, h, 3, rgb.data(), w * 3)) return 2;
    std::ofstream(good + ".txt") << expect;
    // The same picture, but the camera put the scene half under the panel.
    const std::string covered = folder + "/covered.png";
    if (!stbi_write_png(covered.c_str(), w, h, 3, rgb.data(), w * 3)) return 2;
    std::string coveredExpect = expect;
    coveredExpect.replace(coveredExpect.find("framed 110"), 10, "framed  50");
    std::ofstream(covered + ".txt") << coveredExpect;
    // The same picture, but the debug view promised an EPA face that is not drawn.
    const std::string unmarked = folder + "/unmarked.png";
    if (!stbi_write_png(unmarked.c_str(), w, h, 3, rgb.data(), w * 3)) return 2;
    std::ofstream(unmarked + ".txt") << expect << "mark epa on-A 200 120 64 115 242 0.3\n";
    const int blankResult = checkScreenshot(blank, blank + ".txt");
    const int goodResult = checkScreenshot(good, good + ".txt");
    const int coveredResult = checkScreenshot(covered, covered + ".txt");
    const int unmarkedResult = checkScreenshot(unmarked, unmarked + ".txt");
    std::cout << "self-test: blank image -> " << blankResult << " (want 1), drawn image -> " << goodResult
              << " (want 0), scene under the panel -> " << coveredResult << " (want 1), view not drawn -> "
              << unmarkedResult << " (want 1)\n";
    return blankResult == 1 && goodResult == 0 && coveredResult == 1 && unmarkedResult == 1 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--window") return checkWindow(argv[2]);
    if (argc == 3 && std::string(argv[1]) == "--self-test") return selfTest(argv[2]);
    if (argc < 2 || argc > 3) {
        std::cerr << "usage: check_png IMAGE.png [EXPECTATIONS.txt] | --window SCREEN.xwd | --self-test FOLDER\n";
        return 2;
    }
    return checkScreenshot(argv[1], argc == 3 ? argv[2] : std::string(argv[1]) + ".txt");
}
