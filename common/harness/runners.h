// common/harness/runners.h — the two ways one lab program runs (lab_main.cpp
// chooses with runner_for, harness/options.h).
#pragma once

namespace gllab {

/// The lab in a freeglut window (window_main.cpp). In a build whose headless
/// backend is OSMesa there is no window (no_window.cpp says so and exits 2).
int run_window(int argc, char** argv);
/// One view (or several, --views) to PNG or PAM without a display
/// (headless_main.cpp, over harness/offscreen.h).
int run_headless(int argc, char** argv);

}  // namespace gllab
