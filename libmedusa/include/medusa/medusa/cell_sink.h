// Where the medusa builder sends finished cells (docs/MATH.md §6.5: a cell is output as soon as it
// finishes, so memory holds only the active complex).
#pragma once

#include "medusa/kinetic/trajectories.h"
#include "medusa/medusa/cell.h"
#include "medusa/medusa/run_info.h"
#include "medusa/medusa/timeline.h"

#include <vector>

namespace medusa {

// Receives, in this order: run (optional, at most once, before finish), then interleaved batch,
// frame and cell records, then finish once. Cells arrive in the order they finish, not by id.
class CellSink {
public:
  virtual ~CellSink() = default;
  virtual void run(const RunInfo& /*info*/, const kinetic::Trajectories& /*input*/) {}
  virtual void batch(const BatchRecord& /*batch*/) {}
  virtual void frame(const FrameRecord& /*frame*/) {}
  virtual void cell(const Cell& cell) = 0;
  // The run ended; every remaining cell has been sent with death `end` (docs/MATH.md §6.2).
  virtual void finish(const VirtualTime& /*end*/) {}
};

// Forwards everything to several sinks (e.g. a store writer and an in-memory collector).
class TeeSink : public CellSink {
public:
  explicit TeeSink(std::vector<CellSink*> sinks) : sinks_(std::move(sinks)) {}
  void run(const RunInfo& info, const kinetic::Trajectories& input) override {
    for (CellSink* s : sinks_)
      s->run(info, input);
  }
  void batch(const BatchRecord& b) override {
    for (CellSink* s : sinks_)
      s->batch(b);
  }
  void frame(const FrameRecord& f) override {
    for (CellSink* s : sinks_)
      s->frame(f);
  }
  void cell(const Cell& c) override {
    for (CellSink* s : sinks_)
      s->cell(c);
  }
  void finish(const VirtualTime& end) override {
    for (CellSink* s : sinks_)
      s->finish(end);
  }

private:
  std::vector<CellSink*> sinks_;
};

} // namespace medusa
