#pragma once
// The inspector: the selected body's name, type, mass, inertia, velocities, orientation and
// position, editable. A change is applied through the session as a BodyEdit as soon as it is
// valid; an invalid one (a negative mass, an inertia no rigid body has) stays in the fields,
// with chapter 9's validateEdit message in red, until it is fixed or reverted.

#include "demo_state.h"

namespace stepwise::render {

struct Inspector {
    int body = -1;
    bool pending = false;          // `draft` holds a change the session refused
    BodyEdit draft;
    std::string problem;           // validateEdit's message for the pending draft
    float eulerDegrees[3] = {0, 0, 0};   // kept while its field is dragged (Euler angles jump)
    bool eulerActive = false;
};

void inspectorSection(Inspector& inspector, DemoState& state);

}  // namespace stepwise::render
