// common/gl/throughput.cpp — see throughput.h.
#include "gl/throughput.h"

#include <chrono>
#include <cstdio>
#include <utility>

#include "gl/gl.h"
#include "gl/text.h"

namespace gllab {

Throughput::Throughput(std::vector<std::string> names)
    : names_(std::move(names)), mtri_s_(names_.size(), 0.0) {}

void Throughput::measure_next(const std::function<void(int way)>& draw, std::size_t triangles,
                              double seconds) {
  using Clock = std::chrono::steady_clock;
  glFinish();
  const Clock::time_point start = Clock::now();
  int draws = 0;
  double elapsed = 0;
  do {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw(next_);
    glFinish();
    ++draws;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < seconds);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);  // the timing draws never reach the frame
  mtri_s_[std::size_t(next_)] = draws * double(triangles) / elapsed / 1e6;
  next_ = (next_ + 1) % int(names_.size());
  if (!complete()) ++measured_;
}

void Throughput::reset() {
  mtri_s_.assign(names_.size(), 0.0);
  next_ = measured_ = 0;
}

void Throughput::draw_table(int current, int height) const {
  std::vector<std::string> lines = {"path            Mtri/s   / " + names_[0]};
  for (std::size_t p = 0; p < names_.size(); ++p) {
    char row[96];
    std::snprintf(row, sizeof row, "%-14s %7.2f   %6.2fx%s", names_[p].c_str(), mtri_s_[p],
                  mtri_s_[p] / mtri_s_[0], int(p) == current ? "  <" : "");
    lines.push_back(row);
  }
  const int top = height - 8 - int(lines.size() + 1) * kGlyphHeight;
  draw_text_panel(8, top, lines, {1.f, 0.9f, 0.6f});
}

std::string with_commas(std::size_t n) {
  std::string digits = std::to_string(n);
  for (int k = int(digits.size()) - 3; k > 0; k -= 3) digits.insert(std::size_t(k), ",");
  return digits;
}

}  // namespace gllab
