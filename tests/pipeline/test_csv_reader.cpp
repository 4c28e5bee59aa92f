#include "io_test_support.h"
#include "medusa/io/csv_reader.h"

#include <fstream>

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;

namespace {
std::string csv_error(const std::string& fixture) {
  return io::test::input_error([&] { read_csv(io::test::data("io/" + fixture)); });
}
} // namespace

TEST_CASE("The CSV reader gives exact grid positions, types, names and volumes", "[io][csv]") {
  const CsvContents c = read_csv(io::test::data("io/gap.csv"));
  REQUIRE(c.samples.size() == 9);
  CHECK(c.has_volume);
  const CellSample& s = c.samples[1];
  CHECK(s.mcs == 0);
  CHECK(s.cell_id == 2);
  CHECK(s.type == 2);
  CHECK(s.position == kinetic::GridPoint{4500000, 5250000, 6125000});
  CHECK(s.volume == 120);
  CHECK(s.line == 3);
  CHECK(c.samples[8].position == kinetic::GridPoint{-1000001, 1, 10000000});
  CHECK(c.type_names == std::vector<std::string>{"", "Condensing", "NonCondensing"});
}

TEST_CASE("CSV column names are configurable and volume and type name are optional", "[io][csv]") {
  io::test::TempDir dir;
  std::ofstream(dir.file("renamed.csv")) << "t,id,x,y,z,kind\n5,9,1.5,2,3,1\n";
  CsvOptions o;
  o.columns = {"t", "id", "kind", "x", "y", "z", "", ""};
  const CsvContents c = read_csv(dir.file("renamed.csv"), o);
  REQUIRE(c.samples.size() == 1);
  CHECK(c.samples[0].mcs == 5);
  CHECK(c.samples[0].cell_id == 9);
  CHECK(c.samples[0].type == 1);
  CHECK(c.samples[0].position == kinetic::GridPoint{1500000, 2000000, 3000000});
  CHECK(c.samples[0].volume == -1);
  CHECK_FALSE(c.has_volume);
  CHECK(c.type_names.empty());
}

TEST_CASE("A CSV without a required column names the column and the file", "[io][csv]") {
  CHECK_THAT(csv_error("missing_column.csv"),
             Contains("missing_column.csv:1") && Contains("missing column 'zCOM'"));
}

TEST_CASE("A CSV without several required columns names them all and lists what is required", "[io][csv]") {
  io::test::TempDir dir;
  std::ofstream(dir.file("mine.csv")) << "mcs,id,type,xCOM,y,zCOM\n0,1,1,1,2,3\n";
  CHECK_THAT(
      io::test::input_error([&] { read_csv(dir.file("mine.csv")); }),
      Contains("mine.csv:1: missing columns 'cell_id', 'type_id', 'yCOM'") &&
          Contains("(required: mcs, cell_id, type_id, xCOM, yCOM, zCOM; optional: volume, type_name)"));
}

TEST_CASE("A planar CSV without a z column is told to add one of zeros", "[io][csv]") {
  io::test::TempDir dir;
  std::ofstream(dir.file("flat.csv")) << "mcs,cell_id,type_id,xCOM,yCOM\n0,1,1,1,2\n";
  CHECK_THAT(io::test::input_error([&] { read_csv(dir.file("flat.csv")); }),
             Contains("flat.csv:1: missing column 'zCOM'") &&
                 Contains("for a planar run add a column zCOM of 0 on every row"));
  std::ofstream(dir.file("two.csv")) << "mcs,cell_id,xCOM,yCOM\n0,1,1,2\n";
  CHECK_THAT(io::test::input_error([&] { read_csv(dir.file("two.csv")); }), !Contains("planar run"));
}

TEST_CASE("A non-numeric CSV value names file, line, MCS, cell and column", "[io][csv]") {
  CHECK_THAT(csv_error("non_numeric.csv"),
             Contains("non_numeric.csv:3: MCS 0, cell 2: column xCOM") && Contains("'abc'"));
}

TEST_CASE("A NaN CSV value names file, line, MCS and cell", "[io][csv]") {
  CHECK_THAT(csv_error("nan.csv"), Contains("nan.csv:4: MCS ") && Contains("cell 3") && Contains("yCOM") &&
                                       Contains("not a finite number"));
}

TEST_CASE("A CSV value with more than six decimals is refused at scale 10^6", "[io][csv]") {
  CHECK_THAT(csv_error("too_many_decimals.csv"),
             Contains("too_many_decimals.csv:3") && Contains("cell 2") && Contains("7 decimals"));
  CsvOptions finer;
  finer.scale = 10000000;
  const CsvContents c = read_csv(io::test::data("io/too_many_decimals.csv"), finer);
  REQUIRE(c.samples.size() >= 2);
  CHECK(c.samples[1].position[0] == 40000005);
}

TEST_CASE("An over-precise CSV value points to --round-csv", "[io][csv]") {
  CHECK_THAT(csv_error("too_many_decimals.csv"), Contains("--round-csv"));
}

TEST_CASE("CSV centres are rounded to the grid, ties to even, and the rounding counted on request",
          "[io][csv]") {
  io::test::TempDir dir;
  // Row 1 on the grid; row 2 rounds down by 0.4 and up by 0.3 grid units; row 3 is a tie (to even,
  // 0.5 units) and an exponent.
  std::ofstream(dir.file("fine.csv")) << "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n"
                                         "0,1,1,1.5,2,3\n"
                                         "0,2,1,4.0000004,5.0000007,6\n"
                                         "0,3,2,7.0000015,8.1e-6,9.25E1\n";
  CsvOptions o;
  o.round = true;
  const CsvContents c = read_csv(dir.file("fine.csv"), o);
  REQUIRE(c.samples.size() == 3);
  CHECK(c.samples[0].position == kinetic::GridPoint{1500000, 2000000, 3000000});
  CHECK(c.samples[1].position == kinetic::GridPoint{4000000, 5000001, 6000000});
  CHECK(c.samples[2].position == kinetic::GridPoint{7000002, 8, 92500000});
  CHECK(c.rounding.snapped);
  CHECK(c.rounding.positions == 3);
  CHECK(c.rounding.moved == 2);
  CHECK(c.rounding.max_displacement_num * 2 == c.rounding.max_displacement_den);
  CHECK_THAT(io::test::input_error([&] { read_csv(dir.file("fine.csv")); }),
             Contains("fine.csv:3") && Contains("cell 2") && Contains("xCOM") && Contains("7 decimals"));
}

TEST_CASE("A duplicate (MCS, cell) row in a CSV names both lines", "[io][csv]") {
  CHECK_THAT(csv_error("duplicate.csv"),
             Contains("duplicate.csv:5") && Contains("cell 2") && Contains("MCS 0") && Contains("line 3"));
}

TEST_CASE("A cell that changes type in a CSV is refused", "[io][csv]") {
  CHECK_THAT(csv_error("type_change.csv"), Contains("type_change.csv:5") && Contains("cell 2") &&
                                               Contains("type changes from 2 (line 3) to 1"));
}

TEST_CASE("A CSV row with the wrong number of fields names file, line, MCS and cell", "[io][csv]") {
  CHECK_THAT(csv_error("wrong_fields.csv"),
             Contains("wrong_fields.csv:3: MCS 0, cell 2: expected 9 fields") && Contains("found 8"));
}

TEST_CASE("A truncated gzip CSV is refused naming the file", "[io][csv]") {
  CHECK_THAT(csv_error("truncated.csv.gz"), Contains("truncated.csv.gz") && Contains("truncated"));
}

TEST_CASE("A corrupt gzip CSV is refused naming the file", "[io][csv]") {
  CHECK_THAT(csv_error("corrupt.csv.gz"), Contains("corrupt.csv.gz") && Contains("corrupt"));
}

TEST_CASE("An unreadable CSV is refused naming the file", "[io][csv]") {
  CHECK_THAT(csv_error("no_such_file.csv"), Contains("no_such_file.csv") && Contains("cannot open"));
}

TEST_CASE("A header-only or empty CSV is refused", "[io][csv]") {
  io::test::TempDir dir;
  std::ofstream(dir.file("empty.csv")) << "";
  std::ofstream(dir.file("header.csv")) << "mcs,cell_id,cluster_id,type_id,type_name,xCOM,yCOM,zCOM,volume\n";
  CHECK_THAT(io::test::input_error([&] { read_csv(dir.file("empty.csv")); }),
             Contains("empty.csv") && Contains("empty"));
  CHECK_THAT(io::test::input_error([&] { read_csv(dir.file("header.csv")); }),
             Contains("header.csv") && Contains("no data"));
}

TEST_CASE("A UTF-8 byte order mark before the header is not part of the first column's name", "[io][csv]") {
  io::test::TempDir dir;
  std::ifstream plain(io::test::data("io/gap.csv"), std::ios::binary);
  std::ofstream(dir.file("bom.csv"), std::ios::binary) << "\xEF\xBB\xBF" << plain.rdbuf();
  const CsvContents with_bom = read_csv(dir.file("bom.csv"));
  const CsvContents without = read_csv(io::test::data("io/gap.csv"));
  REQUIRE(with_bom.samples.size() == without.samples.size());
  CHECK(with_bom.samples.front().position == without.samples.front().position);
}

TEST_CASE("Input quoted in a message is cut to about 200 characters with control bytes escaped",
          "[io][csv]") {
  io::test::TempDir dir;
  const std::string header = "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n";
  // A NUL byte inside a number: the message goes on past it, with the byte written \x00.
  std::ofstream(dir.file("nul.csv"), std::ios::binary) << header << std::string("0,1,1,1.5\0junk,2,3\n", 19);
  const std::string nul = io::test::input_error([&] { read_csv(dir.file("nul.csv")); });
  CHECK_THAT(nul, Contains("nul.csv:2") && Contains("'1.5\\x00junk'") && Contains("not a decimal number"));
  CHECK(nul.find('\0') == std::string::npos);
  // A 10 MB field (on a line under the 1 MiB cap, 900 KB here) is quoted by its first 200 characters.
  std::ofstream(dir.file("wide.csv")) << header << "0,1,1," << std::string(900000, '9') << "x,2,3\n";
  const std::string wide = io::test::input_error([&] { read_csv(dir.file("wide.csv")); });
  CHECK_THAT(wide, Contains("wide.csv:2") && Contains("(900001 bytes in all)"));
  CHECK(wide.size() < 400);
  // A header of binary bytes is escaped too.
  std::ofstream(dir.file("binary.csv"), std::ios::binary) << std::string("\x01\x02\xff,b\n0,1\n", 10);
  const std::string binary = io::test::input_error([&] { read_csv(dir.file("binary.csv")); });
  CHECK_THAT(binary, Contains("missing columns 'mcs', 'cell_id'") && Contains("'\\x01\\x02\\xFF,b'"));
}
