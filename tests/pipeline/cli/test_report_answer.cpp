// The plain-words answer of `medusa report` (pipeline/cli/report_answer.cpp) on cluster counts worked
// out by hand: each sentence and the verdict follow from b0 at the frames and the join times alone.
#include "report_answer.h"

#include <catch2/catch.hpp>

using medusa::cli::clusters_apart_text;
using medusa::cli::run_verdict;
using medusa::cli::type_course;

namespace {
const std::vector<std::int64_t> five_frames = {0, 100, 200, 300, 400};
}

TEST_CASE("A type that becomes one cluster and stays one gathers at the first frame of that stretch") {
  const auto c = type_course(five_frames, {7, 3, 1, 1, 1}, {10, 20, 31, 40, 50, 59});
  REQUIRE(c.gathered_at == 200.0);
  CHECK_FALSE(c.one_from_start);
  // Six joins: the median is the third (half of them by then), the last the sixth.
  CHECK(c.text == "7 clusters at MCS 0, one cluster from MCS 200 to the end (MCS 400) "
                  "(6 joins, half by MCS 31, all by MCS 59)");
}

TEST_CASE("A type that is one cluster at a frame but split again at the end does not gather") {
  const auto c = type_course(five_frames, {7, 4, 1, 2, 4}, {5, 150});
  CHECK_FALSE(c.gathered_at);
  CHECK(c.text == "7 clusters at MCS 0, 4 at MCS 400, one cluster at MCS 200 but split again by the end "
                  "(2 joins, half by MCS 5, all by MCS 150)");
}

TEST_CASE("A type that is never one cluster says so, and that no cluster joined another") {
  const auto c = type_course(five_frames, {5, 5, 5, 5, 5}, {});
  CHECK_FALSE(c.gathered_at);
  CHECK(c.text == "5 clusters at MCS 0, 5 at MCS 400, never one cluster after MCS 0 "
                  "(no cluster ever joined another)");
}

TEST_CASE("A type that is one cluster at the first frame does not gather, even if one again at the end") {
  const auto c = type_course({0, 100, 200}, {1, 3, 1}, {150});
  CHECK_FALSE(c.gathered_at);
  CHECK_FALSE(c.one_from_start);
  CHECK(c.text == "one cluster at MCS 0, up to 3 clusters later, one cluster at the last frame (MCS 200) "
                  "(1 join, at MCS 150)");
}

TEST_CASE("Clusters of the first frame already joined through cells present at that frame only are said "
          "beside the joins") {
  // Four clusters at MCS 0, two of them bridged in space-time by cells that leave at MCS 0: their
  // merges in the frames after it are no joins, so one join takes 4 clusters to one.
  const auto c = type_course(five_frames, {4, 2, 1, 1, 1}, {18}, 2);
  CHECK(c.text == "4 clusters at MCS 0, one cluster from MCS 200 to the end (MCS 400) "
                  "(1 join, at MCS 18; 2 of the clusters at MCS 0 were already joined to another through "
                  "cells present at that frame only)");
  const auto one = type_course(five_frames, {3, 3, 2, 2, 2}, {50}, 1);
  CHECK(one.text == "3 clusters at MCS 0, 2 at MCS 400, never one cluster after MCS 0 (1 join, at MCS 50; 1 "
                    "of the clusters at MCS 0 was already joined to another through cells present at that "
                    "frame only)");
}

TEST_CASE("The verdict names the types that gather, or says why it cannot tell") {
  const auto gathers = type_course(five_frames, {7, 3, 1, 1, 1}, {59});
  const auto split = type_course(five_frames, {12, 8, 4, 2, 2}, {265});
  const auto one = type_course(five_frames, {1, 1, 1, 1, 1}, {});
  CHECK(
      run_verdict({{"type 1 (Condensing)", gathers, "", ""}, {"type 2", split, "", ""}}, "3") ==
      "sorts at radius 3: type 1 (Condensing) gathers into one cluster by MCS 200 and stays one to the end");
  CHECK(run_verdict({{"type 1", split, "", ""}, {"type 2", split, "", ""}}, "3") ==
        "has no type in one cluster to the end at radius 3: type 1 goes from 12 clusters "
        "to 2; type 2 goes from 12 clusters to 2");
  CHECK(run_verdict({{"type 1", one, "", ""}, {"type 2", one, "", ""}}, "4.5")
            .rfind("cannot tell at radius 4.5: every type is one "
                   "cluster from the first frame on",
                   0) == 0);
}

TEST_CASE("A verdict without a gathering type says how far each type got, with its contacts") {
  const auto most_of_the_way = type_course(five_frames, {22, 9, 4, 2, 2}, {10, 20, 30});
  const auto one = type_course(five_frames, {1, 1, 1, 1, 1}, {});
  const auto ends_in_one_again = type_course({0, 100, 200}, {1, 3, 1}, {150});
  CHECK(run_verdict({{"type 1 (Condensing)", most_of_the_way, "heterotypic contacts 0.667 \u2192 0.268", ""},
                     {"type 2 (NonCondensing)", one, "heterotypic contacts 0.310 \u2192 0.110", ""},
                     {"type 3", ends_in_one_again, "", ""}},
                    "2.7") ==
        "has no type in one cluster to the end at radius 2.7: type 1 (Condensing) goes from "
        "22 clusters to 2, heterotypic contacts 0.667 \u2192 0.268; type 2 (NonCondensing) is one cluster "
        "throughout, heterotypic contacts 0.310 \u2192 0.110; type 3 has one cluster at the first and at the "
        "last frame");
}

TEST_CASE("A verdict without a gathering type names the few cells outside each type's largest cluster") {
  const auto most_of_the_way = type_course(five_frames, {22, 9, 4, 2, 2}, {10, 20, 30});
  const auto control = type_course(five_frames, {12, 8, 4, 3, 3}, {10});
  CHECK(run_verdict({{"type 1 (Condensing)", most_of_the_way, "heterotypic contacts 0.667 \u2192 0.268",
                      clusters_apart_text({99, 98, false, {166}, 1})},
                     {"type 2", control, "heterotypic contacts 0.698 \u2192 0.680",
                      clusters_apart_text({125, 122, false, {17, 30, 230}, 2})}},
                    "2.7") ==
        "has no type in one cluster to the end at radius 2.7: type 1 (Condensing) goes from 22 clusters to 2 "
        "(the largest holds 98 of its 99 cells; cell 166 is outside it), heterotypic contacts 0.667 \u2192 "
        "0.268; "
        "type 2 goes from 12 clusters to 3 (the largest holds 122 of its 125 cells; cells 17, 30 and 230 are "
        "outside it, in 2 other clusters), heterotypic contacts 0.698 \u2192 0.680");
}

TEST_CASE("Cells outside the largest cluster are named only when few and the largest is not tied") {
  CHECK(clusters_apart_text({10, 10, false, {}, 0}).empty());
  CHECK(clusters_apart_text({0, 0, false, {}, 0}).empty());
  CHECK(clusters_apart_text({10, 8, false, {4, 9}, 2}) ==
        "the largest holds 8 of its 10 cells; cells 4 and 9 are outside it, each alone");
  CHECK(clusters_apart_text({10, 8, false, {4, 9}, 1}) ==
        "the largest holds 8 of its 10 cells; cells 4 and 9 are outside it, in one other cluster");
  CHECK(clusters_apart_text({94, 33, false, {1, 2, 3, 4, 5, 6}, 3}) ==
        "the largest holds 33 of its 94 cells");
  CHECK(clusters_apart_text({10, 5, true, {}, 0}) == "the largest holds 5 of its 10 cells");
}

TEST_CASE("A type that splits after the first frame without any join says why there is no join") {
  const auto c = type_course({0, 100, 200, 300}, {1, 5, 2, 1}, {});
  CHECK(c.text == "one cluster at MCS 0, up to 5 clusters later, one cluster at the last frame (MCS 300) "
                  "(no join: the pieces that split off later were part of one cluster before)");
}
