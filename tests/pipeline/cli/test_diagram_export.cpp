// The diagram exports name each type beside its id (pipeline/cli/diagram_export.cpp), in CSV as
// RFC 4180 quotes a field, on diagrams made by hand.
#include "diagram_export.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <sstream>

using namespace medusa;

namespace {

std::vector<persistence::Diagram> diagrams() {
  persistence::Diagram all, one, three;
  all.cell_type = persistence::all_types;
  one.cell_type = 1;
  three.cell_type = 3;
  for (persistence::Diagram* d : {&all, &one, &three}) {
    persistence::PersistencePair p;
    p.birth = 0;
    p.death = 100;
    d->pairs.push_back(p);
  }
  one.pairs[0].death = std::numeric_limits<double>::infinity();
  return {all, one, three};
}

// Type 1 named with a comma and a quote; type 3 beyond the names, as a type the run does not name.
const cli::TypeNames names = {"Medium", "Light, \"dark\""};

} // namespace

TEST_CASE("The diagrams CSV names each type beside its id, quoting a name with a comma or a quote",
          "[cli][export]") {
  std::ostringstream out;
  cli::write_csv(out, diagrams(), names, "run-7");
  CHECK(out.str() == "# medusa run run-7\n"
                     "birth,death,dimension,type,direction,type_name\n"
                     "0,100,0,all,forward,\n"
                     "0,inf,0,1,forward,\"Light, \"\"dark\"\"\"\n"
                     "0,100,0,3,forward,\n");
}

TEST_CASE("The diagrams text and JSON name each type beside its id", "[cli][export]") {
  std::ostringstream text, json;
  cli::write_pairs_text(text, diagrams(), names);
  CHECK(text.str() == "# type all, forward, 1 pairs (birth death dim)\n0 100 0\n"
                      "# type 1 (Light, \"dark\"), forward, 1 pairs (birth death dim)\n0 inf 0\n"
                      "# type 3, forward, 1 pairs (birth death dim)\n0 100 0\n");
  cli::write_json(json, diagrams(), names);
  const nlohmann::json listed = nlohmann::json::parse(json.str())["diagrams"];
  REQUIRE(listed.size() == 3);
  CHECK(listed[0]["type"] == "all");
  CHECK(listed[0]["type_name"] == "");
  CHECK(listed[1]["type"] == "1");
  CHECK(listed[1]["type_name"] == "Light, \"dark\"");
  CHECK(listed[1]["pairs"][0]["death"] == "inf");
  CHECK(listed[2]["type_name"] == "");
}
