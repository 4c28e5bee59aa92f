// The periodic domain rebuilt from a store's run record (pipeline/cli/recorded_domain.cpp), as
// `medusa report` sweeps a periodic store on the torus: the recorded axes and periods, nothing else.
#include "recorded_domain.h"

#include "medusa/core/error.h"

#include <catch2/catch.hpp>

using medusa::cli::recorded_domain;

TEST_CASE("A store periodic in x and y gives those axes with the recorded periods") {
  medusa::RunInfo run;
  run.periodic_axes = "x,y";
  run.periodic_lengths = {50000000, 40000000, 0};
  const medusa::io::PeriodicDomain d = recorded_domain(run, 1000000, "run.h5");
  CHECK(d.periodic == std::array<bool, 3>{true, true, false});
  CHECK(d.period == std::array<std::int64_t, 3>{50000000, 40000000, 0});
  CHECK(d.lattice == std::array<std::int64_t, 3>{50, 40, 0});
  CHECK(d.origin == std::array<std::int64_t, 3>{0, 0, 0});
  CHECK(d.axes() == "x,y");
}

TEST_CASE("An open store gives no periodic axis, whatever lengths it holds") {
  medusa::RunInfo run;
  run.periodic_lengths = {7, 0, 0};
  CHECK_FALSE(recorded_domain(run, 1000000, "run.h5").any());
}

TEST_CASE("A periodic axis without a positive period or an unknown axis is a store error naming the store") {
  medusa::RunInfo run;
  run.periodic_axes = "z";
  CHECK_THROWS_AS(recorded_domain(run, 1000000, "run.h5"), medusa::StoreError);
  CHECK_THROWS_WITH(recorded_domain(run, 1000000, "run.h5"),
                    Catch::Contains("run.h5") && Catch::Contains("z"));
  run.periodic_axes = "w";
  run.periodic_lengths = {0, 0, 10};
  CHECK_THROWS_AS(recorded_domain(run, 1000000, "run.h5"), medusa::StoreError);
}
