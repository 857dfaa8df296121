// common/gl/throughput.h — live triangles per second of a few ways to draw
// one mesh, for a lab's window panel (lab 05's four submission paths). Not the
// lesson: the lab's own draw calls are timed through a callback, in the
// window only (State::interactive), so headless pictures never show a number.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace gllab {

class Throughput {
 public:
  /// One row name per way of drawing; the first is the baseline of the ratios.
  explicit Throughput(std::vector<std::string> names);

  /// Times the next way (round-robin, one per call): glFinish, then glClear +
  /// draw(way) + glFinish again and again until at least `seconds` have
  /// passed, so the time covers GL's work and not just the calls. Leaves the
  /// colour and depth buffers cleared, as the runner hands them to a view.
  void measure_next(const std::function<void(int way)>& draw, std::size_t triangles,
                    double seconds = 0.02);
  /// Forgets every rate (a new mesh starts a new round).
  void reset();
  /// True once every way has a rate.
  bool complete() const { return measured_ == static_cast<int>(names_.size()); }
  /// A panel in the bottom-left corner of a window `height` pixels high: a
  /// row per way, Mtri/s and the ratio to the first, `current` marked "<".
  void draw_table(int current, int height) const;

 private:
  std::vector<std::string> names_;
  std::vector<double> mtri_s_;
  int next_ = 0, measured_ = 0;
};

/// 16384 as "16,384", for counts in a panel.
std::string with_commas(std::size_t n);

}  // namespace gllab
