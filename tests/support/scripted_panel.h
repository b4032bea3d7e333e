#pragma once
// A demo panel for tests: it plays a user who moves the controls a test names (and, if asked,
// presses every button and flips every checkbox), and records every control and line it was
// shown. Every suite's scene views are driven through this one class.

#include "app/panel.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace stepwise::test {

class ScriptedPanel final : public Panel {
public:
    // What the "user" does.
    std::map<std::string, float> floats;   // float sliders to move, by label
    std::map<std::string, int> ints;       // int sliders and combos to set, by label
    bool pressEveryButton = false;
    bool flipEveryCheckbox = false;

    // What the panel was shown.
    std::vector<std::string> lines;        // text lines
    std::vector<std::string> labels;       // every control's label, in order
    int sliders = 0, buttons = 0, checkboxes = 0, combos = 0;

    bool shown(const std::string& label) const {
        return std::find(labels.begin(), labels.end(), label) != labels.end();
    }

    void text(const std::string& line) override { lines.push_back(line); }
    bool checkbox(const std::string& label, bool& value) override {
        labels.push_back(label);
        ++checkboxes;
        if (!flipEveryCheckbox) return false;
        value = !value;
        return true;
    }
    bool sliderFloat(const std::string& label, float& value, float, float) override {
        labels.push_back(label);
        ++sliders;
        return take(floats, label, value);
    }
    bool sliderInt(const std::string& label, int& value, int, int max) override {
        labels.push_back(label);
        ++sliders;
        if (!take(ints, label, value)) return false;
        value = std::min(value, max);
        return true;
    }
    bool button(const std::string& label) override {
        labels.push_back(label);
        ++buttons;
        return pressEveryButton;
    }
    bool combo(const std::string& label, int& index, const char* const*, int count) override {
        labels.push_back(label);
        ++combos;
        if (!take(ints, label, index)) return false;
        index = std::clamp(index, 0, count - 1);
        return true;
    }

private:
    template <class Value>
    static bool take(const std::map<std::string, Value>& script, const std::string& label, Value& value) {
        const auto found = script.find(label);
        if (found == script.end()) return false;
        value = found->second;
        return true;
    }
};

}  // namespace stepwise::test
