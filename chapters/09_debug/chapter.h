#pragma once
// Chapter 9 adds no stage: its tools look at the step, rewind it and replay it, and the step
// itself is chapter 8's. What it adds is in the headers below, all headless (the panels that show
// them are the renderer's, renderer_dx12/).

#include "08_joints/chapter.h"
#include "09_debug/body_edit.h"
#include "09_debug/debug_session.h"
#include "09_debug/debug_views.h"
#include "09_debug/hit_tree.h"
#include "09_debug/history.h"
#include "09_debug/ray_cast.h"
#include "09_debug/recording.h"
