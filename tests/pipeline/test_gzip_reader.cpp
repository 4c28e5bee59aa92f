#include "io_test_support.h"
#include "medusa/io/gzip_reader.h"

#include <fstream>
#include <iterator>
#include <string>
#include <vector>
#include <zlib.h>

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;

namespace {
void write_gzip(const std::string& path, const std::string& text) {
  gzFile f = gzopen(path.c_str(), "wb");
  REQUIRE(f != nullptr);
  REQUIRE(gzwrite(f, text.data(), static_cast<unsigned>(text.size())) == static_cast<int>(text.size()));
  REQUIRE(gzclose(f) == Z_OK);
}
} // namespace

TEST_CASE("Plain and gzip files read the same lines and tokens", "[io][gzip]") {
  io::test::TempDir dir;
  const std::string text = "a,b\r\n  12 34\n\nlast line without newline";
  { std::ofstream(dir.file("plain.txt"), std::ios::binary) << text; }
  write_gzip(dir.file("packed.txt.gz"), text);
  for (const std::string name : {"plain.txt", "packed.txt.gz"}) {
    CAPTURE(name);
    GzipReader lines(dir.file(name));
    std::string line;
    REQUIRE(lines.next_line(line));
    CHECK(line == "a,b");
    REQUIRE(lines.next_line(line));
    CHECK(line == "  12 34");
    REQUIRE(lines.next_line(line));
    CHECK(line.empty());
    REQUIRE(lines.next_line(line));
    CHECK(line == "last line without newline");
    CHECK(lines.line() == 4);
    CHECK_FALSE(lines.next_line(line));

    GzipReader tokens(dir.file(name));
    std::vector<std::pair<std::string, std::int64_t>> got;
    std::string_view t;
    while (tokens.next_token(t))
      got.emplace_back(std::string(t), tokens.line());
    const std::vector<std::pair<std::string, std::int64_t>> expected = {
        {"a,b", 1}, {"12", 2}, {"34", 2}, {"last", 4}, {"line", 4}, {"without", 4}, {"newline", 4}};
    CHECK(got == expected);
  }
}

TEST_CASE("Tokens spanning buffer refills come out whole", "[io][gzip]") {
  io::test::TempDir dir;
  std::string text;
  for (int k = 0; k < 100000; ++k)
    text += std::to_string(k) + (k % 9 == 8 ? " \n" : " ");
  write_gzip(dir.file("many.gz"), text);
  GzipReader in(dir.file("many.gz"));
  std::string_view t;
  int k = 0;
  while (in.next_token(t)) {
    REQUIRE(t == std::to_string(k));
    ++k;
  }
  CHECK(k == 100000);
}

TEST_CASE("A truncated gzip file is an error naming the file", "[io][gzip]") {
  const std::string path = io::test::data("io/truncated.csv.gz");
  const std::string m = io::test::input_error([&] {
    GzipReader in(path);
    std::string line;
    while (in.next_line(line)) {
    }
  });
  CHECK_THAT(m, Contains(path) && Contains("truncated"));
}

TEST_CASE("A gzip file cut short hands out its whole lines before the cut and names the line where they stop",
          "[io][gzip]") {
  // 5,000 lines decode to less than the reader's first request, so the cut meets the first read; 20,000
  // lines meet it at a later one.
  const int count = GENERATE(5000, 20000);
  CAPTURE(count);
  io::test::TempDir dir;
  std::string text;
  std::vector<std::string> lines;
  for (int k = 0; k < count; ++k) {
    lines.push_back("row " + std::to_string(k) + "," + std::to_string(k * 7919 % 10007));
    text += lines.back() + "\n";
  }
  write_gzip(dir.file("whole.csv.gz"), text);
  std::ifstream whole(dir.file("whole.csv.gz"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(whole)), std::istreambuf_iterator<char>());
  // Cut at 60% of the compressed bytes: the lines decoded before the cut come out before the error.
  std::ofstream(dir.file("cut.csv.gz"), std::ios::binary) << bytes.substr(0, bytes.size() * 3 / 5);
  GzipReader in(dir.file("cut.csv.gz"));
  std::size_t read = 0;
  const std::string m = io::test::input_error([&] {
    std::string line;
    while (in.next_line(line)) {
      REQUIRE(read < lines.size());
      REQUIRE(line == lines[read]);
      ++read;
    }
  });
  CAPTURE(m, read);
  CHECK(read > lines.size() / 3);
  CHECK(read < lines.size());
  CHECK_THAT(m, Contains("cut.csv.gz") && Contains("truncated") &&
                    Contains("near line " + std::to_string(read + 1)));
}

TEST_CASE("A corrupt gzip file is an error naming the file", "[io][gzip]") {
  const std::string path = io::test::data("io/corrupt.csv.gz");
  const std::string m = io::test::input_error([&] {
    GzipReader in(path);
    std::string line;
    while (in.next_line(line)) {
    }
  });
  CHECK_THAT(m, Contains(path) && Contains("corrupt"));
}

TEST_CASE("A missing file is an error naming it", "[io][gzip]") {
  CHECK_THAT(io::test::input_error([] { GzipReader in("/nonexistent/cells.csv.gz"); }),
             Contains("/nonexistent/cells.csv.gz") && Contains("cannot open"));
}

TEST_CASE("Raw bytes follow a text line exactly", "[io][gzip]") {
  io::test::TempDir dir;
  const std::string text = std::string("HEAD 3\n") + std::string("\x00\n\xff", 3) + "\nTAIL";
  write_gzip(dir.file("b.gz"), text);
  GzipReader in(dir.file("b.gz"));
  std::string line;
  REQUIRE(in.next_line(line));
  CHECK(line == "HEAD 3");
  char bytes[3];
  in.read_bytes(bytes, 3);
  CHECK(bytes[0] == '\0');
  CHECK(bytes[1] == '\n');
  CHECK(static_cast<unsigned char>(bytes[2]) == 0xff);
  std::string_view t;
  REQUIRE(in.next_token(t));
  CHECK(t == "TAIL");
  CHECK_THAT(io::test::input_error([&] { in.read_bytes(bytes, 1); }), Contains("b.gz"));
}

TEST_CASE("A file named .gz that is not gzip is refused as not a gzip file, without echoing its bytes",
          "[io][gzip]") {
  io::test::TempDir dir;
  {
    std::ofstream(dir.file("binary.csv.gz"), std::ios::binary) << std::string("\x7f"
                                                                              "ELF\x02\x01\x01\0\0binary",
                                                                              16);
  }
  const std::string m = io::test::input_error([&] { GzipReader in(dir.file("binary.csv.gz")); });
  CHECK_THAT(m, Contains("binary.csv.gz") && Contains("not a gzip file"));
  CHECK(m.find("ELF") == std::string::npos);
}

TEST_CASE("A line or a value longer than 1 MiB is refused naming its line, before it is held whole",
          "[io][gzip]") {
  io::test::TempDir dir;
  // A gzip bomb in miniature: 3 MiB of digits on line 2 compress to a few KiB.
  write_gzip(dir.file("long.csv.gz"), "mcs,cell_id\n" + std::string(3u << 20, '7') + "\n");
  GzipReader lines(dir.file("long.csv.gz"));
  std::string line;
  REQUIRE(lines.next_line(line));
  CHECK_THAT(io::test::input_error([&] { lines.next_line(line); }),
             Contains("long.csv.gz:2") && Contains("longer than 1 MiB"));
  GzipReader tokens(dir.file("long.csv.gz"));
  std::string_view token;
  REQUIRE(tokens.next_token(token));
  CHECK_THAT(io::test::input_error([&] { tokens.next_token(token); }),
             Contains("long.csv.gz:2") && Contains("longer than 1 MiB"));
  // Exactly 1 MiB is still a line.
  write_gzip(dir.file("limit.csv.gz"), std::string(max_line_bytes, '7') + "\nnext\n");
  GzipReader limit(dir.file("limit.csv.gz"));
  REQUIRE(limit.next_line(line));
  CHECK(line.size() == max_line_bytes);
}
