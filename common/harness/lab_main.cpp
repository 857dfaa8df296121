// common/harness/lab_main.cpp — main() of every lab program: build/bin/<lab> opens a
// window, build/bin/<lab> --headless (or --out, --views, ...) renders without a display.
// One executable serves both because every GL library it links goes through GLVND
// (libOpenGL, libGLX, libEGL: docs/platform.md, "One program per lab").
#include <string>
#include <vector>

#include "harness/options.h"
#include "harness/runners.h"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  return gllab::runner_for(args) == gllab::Runner::kHeadless ? gllab::run_headless(argc, argv)
                                                             : gllab::run_window(argc, argv);
}
