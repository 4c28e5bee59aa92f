// A small valid store for the fault tests: the worked flip of docs/MATH.md §B (5 vertices, 2 frames,
// 31 cells) streamed through libmedusa's builder into a StoreWriter; support/store_corruption.h damages it.
#pragma once

#include "appendix_b.h"
#include "medusa/medusa/store_writer.h"
#include "medusa_fixtures.h"
#include "support/store_corruption.h"

#include <string>

namespace medusa::test {

inline void write_small_store(const std::string& path) {
  medusa::StoreWriter writer(path);
  play_into(appendix_b_stream(), writer, 5, 2);
}

} // namespace medusa::test
