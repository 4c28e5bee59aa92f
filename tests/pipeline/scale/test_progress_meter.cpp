// The progress meter of `medusa run` (pipeline/cli/progress_meter.h) on a string stream.
#include "progress_meter.h"

#include <catch2/catch.hpp>

#include <sstream>

using medusa::cli::format_duration;
using medusa::cli::ProgressMeter;

namespace {

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
    ++n;
  return n;
}

} // namespace

TEST_CASE("Quiet wins over --progress and a terminal shows progress without it", "[cli][progress]") {
  using Mode = ProgressMeter::Mode;
  CHECK(ProgressMeter::choose(true, true, true) == Mode::off);
  CHECK(ProgressMeter::choose(false, true, true) == Mode::off);
  CHECK(ProgressMeter::choose(true, true, false) == Mode::off);
  CHECK(ProgressMeter::choose(false, false, true) == Mode::terminal);
  CHECK(ProgressMeter::choose(true, false, true) == Mode::terminal);
  CHECK(ProgressMeter::choose(true, false, false) == Mode::lines);
  CHECK(ProgressMeter::choose(false, false, false) == Mode::off);
}

TEST_CASE("Durations print as minutes and seconds, with hours when needed", "[cli][progress]") {
  CHECK(format_duration(0) == "0:00");
  CHECK(format_duration(65) == "1:05");
  CHECK(format_duration(59.6) == "1:00");
  CHECK(format_duration(7387) == "2:03:07");
  CHECK(format_duration(-3) == "0:00");
}

TEST_CASE("Line mode prints one line per frame with stage, frame k of K, rate and ETA", "[cli][progress]") {
  std::ostringstream out;
  {
    ProgressMeter meter(out, ProgressMeter::Mode::lines);
    meter.stage("reading x");
    meter.start_kinetic(4);
    meter.update(1, 0);
    meter.update(2, 10);
    meter.update(3, 20);
    meter.finish_kinetic(30);
    meter.stage("filtrations");
  }
  const std::string text = out.str();
  INFO(text);
  CHECK(text.rfind("medusa: reading x\nmedusa: kinetic alpha complex over 4 frames\n", 0) == 0);
  CHECK(count(text, "frame 1/4, 0 events") == 1);
  CHECK(count(text, "frame 2/4, 10 events") == 1);
  CHECK(count(text, "frame 3/4, 20 events") == 1);
  CHECK(count(text, "frame 4/4, 30 events") == 1);
  CHECK(count(text, "events/s") == 4);
  // No estimate before a slab is done, an estimate while slabs remain, none at the end.
  CHECK(text.find("frame 1/4, 0 events, 0 events/s, elapsed 0:00, ETA ~?\n") != std::string::npos);
  CHECK(count(text, "ETA ~") == 3);
  CHECK(text.find(", done\nmedusa: filtrations\n") != std::string::npos);
  CHECK(text.find('\r') == std::string::npos);
}

TEST_CASE("Terminal mode rewrites one line in place and ends it before the next stage", "[cli][progress]") {
  std::ostringstream out;
  {
    ProgressMeter meter(out, ProgressMeter::Mode::terminal);
    meter.start_kinetic(2);
    meter.update(1, 5);
    meter.finish_kinetic(7);
    meter.stage("reduction");
  }
  const std::string text = out.str();
  INFO(text);
  CHECK(count(text, "\r") == 2);
  CHECK(count(text, "\n") == 3);
  CHECK(text.find("frame 2/2, 7 events") != std::string::npos);
  // The last kinetic line may be padded with spaces over a longer line it replaces.
  const std::string tail = "\nmedusa: reduction\n";
  REQUIRE(text.size() > tail.size());
  CHECK(text.compare(text.size() - tail.size(), tail.size(), tail) == 0);
  const std::string last_kinetic = text.substr(0, text.size() - tail.size());
  const std::size_t done = last_kinetic.rfind(", done");
  REQUIRE(done != std::string::npos);
  CHECK(last_kinetic.find_first_not_of(' ', done + 6) == std::string::npos);
}

TEST_CASE("Off mode prints nothing", "[cli][progress]") {
  std::ostringstream out;
  {
    ProgressMeter meter(out, ProgressMeter::Mode::off);
    meter.stage("reading");
    meter.start_kinetic(3);
    meter.update(2, 1);
    meter.finish_kinetic(2);
  }
  CHECK(out.str().empty());
}
