// Progress of `medusa run` on stderr: the stage, and during the kinetic stage frame k of K, events
// per second, elapsed time and an estimate of the time left.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>

namespace medusa::cli {

class ProgressMeter {
public:
  enum class Mode {
    off,      // nothing is printed
    terminal, // one line rewritten in place ('\r'), at most a few times per second
    lines     // one line per update: at every frame, and at most once per 5 s between frames
  };

  // --quiet wins over --progress; without either, progress shows only on a terminal.
  static Mode choose(bool progress, bool quiet, bool is_terminal);

  ProgressMeter(std::ostream& out, Mode mode);
  ~ProgressMeter();
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  // A stage begins: one line "medusa: <name>" (ending the in-place kinetic line first).
  void stage(const std::string& name);

  // The kinetic stage begins on a run of `frames` frames.
  void start_kinetic(std::size_t frames);
  // `events` events so far; `frames_reached` frames (1..K) reached. A new frame always prints; in
  // between, updates are rate-limited.
  void update(std::size_t frames_reached, std::uint64_t events);
  // The last frame is reached: prints the final kinetic line.
  void finish_kinetic(std::uint64_t events);

private:
  using Clock = std::chrono::steady_clock;
  void print_kinetic(std::size_t frames_reached, std::uint64_t events);
  void end_line();

  std::ostream& out_;
  Mode mode_;
  std::size_t frames_ = 0;
  std::size_t last_frame_printed_ = 0;
  Clock::time_point kinetic_start_;
  Clock::time_point last_print_;
  double frame_elapsed_ = 0.0; // kinetic seconds when the last frame was reached
  bool line_open_ = false;     // a terminal line without its newline yet
  std::size_t line_width_ = 0;
};

// "1:05" or "2:03:07" for a number of seconds.
std::string format_duration(double seconds);

} // namespace medusa::cli
