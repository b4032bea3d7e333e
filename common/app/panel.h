#pragma once
// Demo-panel controls, described without any UI library: renderer_dx12 implements this with
// Dear ImGui; headless runs use no panel at all. Each call returns true when the user changed
// the value this frame.

#include <string>

namespace stepwise {

class Panel {
public:
    virtual ~Panel() = default;
    virtual void text(const std::string& line) = 0;
    virtual bool checkbox(const std::string& label, bool& value) = 0;
    virtual bool sliderFloat(const std::string& label, float& value, float min, float max) = 0;
    virtual bool sliderInt(const std::string& label, int& value, int min, int max) = 0;
    virtual bool button(const std::string& label) = 0;
    /// A choice among labels; `index` selects one.
    virtual bool combo(const std::string& label, int& index, const char* const* items, int count) = 0;
};

}  // namespace stepwise
