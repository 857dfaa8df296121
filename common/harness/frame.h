// common/harness/frame.h — one frame, the same in both runners.
#pragma once

#include <string>
#include <vector>

#include "harness/lab.h"

namespace gllab {

/// Sets the viewport, clears the colour, depth and stencil buffers, calls the
/// current view's draw function between a full push and pop of GL state (so
/// no frame leaks state into the next), draws the help overlay when
/// state.help is on, and checks glGetError(). Errors go to
/// report_frame_error().
void draw_frame(const Lab& lab, const State& state);

/// Lines of the help overlay: title, view, keys, parameters.
std::vector<std::string> help_lines(const Lab& lab, const State& state);

/// Red lines at the bottom of the frame (the window runner shows errors so).
void draw_error_lines(const std::vector<std::string>& errors);

}  // namespace gllab
