#include "progress_meter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace medusa::cli {

ProgressMeter::Mode ProgressMeter::choose(bool progress, bool quiet, bool is_terminal) {
  if (quiet)
    return Mode::off;
  if (is_terminal)
    return Mode::terminal;
  return progress ? Mode::lines : Mode::off;
}

ProgressMeter::ProgressMeter(std::ostream& out, Mode mode) : out_(out), mode_(mode) {}

ProgressMeter::~ProgressMeter() { end_line(); }

void ProgressMeter::end_line() {
  if (line_open_) {
    out_ << "\n" << std::flush;
    line_open_ = false;
    line_width_ = 0;
  }
}

void ProgressMeter::stage(const std::string& name) {
  if (mode_ == Mode::off)
    return;
  end_line();
  out_ << "medusa: " << name << "\n" << std::flush;
}

void ProgressMeter::start_kinetic(std::size_t frames) {
  frames_ = frames;
  last_frame_printed_ = 0;
  kinetic_start_ = Clock::now();
  last_print_ = kinetic_start_;
  stage("kinetic alpha complex over " + std::to_string(frames) + " frames");
}

void ProgressMeter::update(std::size_t frames_reached, std::uint64_t events) {
  if (mode_ == Mode::off)
    return;
  const auto now = Clock::now();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  const bool new_frame = frames_reached != last_frame_printed_;
  // A log gets a line per frame and at most one every 5 s in between; a terminal a few per second.
  const double interval = mode_ == Mode::terminal ? 0.25 : 5.0;
  if (new_frame || since >= interval)
    print_kinetic(frames_reached, events);
}

void ProgressMeter::finish_kinetic(std::uint64_t events) {
  if (mode_ == Mode::off)
    return;
  if (last_frame_printed_ != frames_)
    print_kinetic(frames_, events);
  end_line();
}

void ProgressMeter::print_kinetic(std::size_t frames_reached, std::uint64_t events) {
  last_print_ = Clock::now();
  const double elapsed = std::chrono::duration<double>(last_print_ - kinetic_start_).count();
  if (frames_reached != last_frame_printed_)
    frame_elapsed_ = elapsed;
  last_frame_printed_ = frames_reached;
  // The estimate assumes the remaining slabs (frame to frame) take the mean time of those done
  // (the first one includes building the initial triangulation), less the time already spent in
  // the current slab: a guess, as the number of events per slab varies, hence the "~".
  const std::size_t slabs = frames_ > 0 ? frames_ - 1 : 0;
  const std::size_t done = frames_reached > 0 ? frames_reached - 1 : 0;
  std::string eta = "ETA ~?";
  if (done >= slabs) {
    eta = "done";
  } else if (done > 0) {
    const double mean = frame_elapsed_ / static_cast<double>(done);
    eta = "ETA ~" + format_duration(
                        std::max(0.0, mean * static_cast<double>(slabs - done) - (elapsed - frame_elapsed_)));
  }
  char rate[64];
  std::snprintf(rate, sizeof rate, "%.0f events/s",
                elapsed > 0 ? static_cast<double>(events) / elapsed : 0.0);
  const std::string line = "medusa: kinetic: frame " + std::to_string(frames_reached) + "/" +
                           std::to_string(frames_) + ", " + std::to_string(events) + " events, " + rate +
                           ", elapsed " + format_duration(elapsed) + ", " + eta;
  if (mode_ == Mode::terminal) {
    // Spaces over what is left of a longer previous line.
    const std::size_t pad = line_width_ > line.size() ? line_width_ - line.size() : 0;
    out_ << "\r" << line << std::string(pad, ' ') << std::flush;
    line_open_ = true;
    line_width_ = line.size();
  } else {
    out_ << line << "\n" << std::flush;
  }
}

std::string format_duration(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  const long h = total / 3600, m = (total / 60) % 60, s = total % 60;
  char buffer[32];
  if (h > 0)
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", h, m, s);
  else
    std::snprintf(buffer, sizeof buffer, "%ld:%02ld", m, s);
  return buffer;
}

} // namespace medusa::cli
