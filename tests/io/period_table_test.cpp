// The "T value" tables of user spectra and sigma files: rows with their lines, and errors that
// name the file and the line.
#include "io/period_table.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "../support/scratch_dir.hpp"
#include "core/error.hpp"

namespace pound {
namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string p = test::process_scratch_dir() / name;
  std::ofstream(p) << text;
  return p;
}

std::string error_of(const std::string& path) {
  try {
    read_period_table(path, "the test table", "'T v'");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PeriodTable, RowsKeepTheirLinesAndTheValuesAsWritten) {
  const std::string p = write("ok.txt", "# T v\n\n0.1  2.5e-1\r\n  \t\n0.5 7\n# end\n2 0\n");
  const auto rows = read_period_table(p, "the test table", "'T v'");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].period, 0.1);
  EXPECT_EQ(rows[0].value, 0.25);
  EXPECT_EQ(rows[0].text, "2.5e-1");
  EXPECT_EQ(rows[0].where, p + ":3");
  EXPECT_EQ(rows[1].where, p + ":5");
  EXPECT_EQ(rows[2].period, 2.0);
  EXPECT_EQ(rows[2].value, 0.0);
  EXPECT_TRUE(read_period_table(write("empty.txt", "# nothing\n"), "t", "'T v'").empty());
}

TEST(PeriodTable, SkipsAUtf8ByteOrderMark) {
  // A "UTF-8" file saved by a Windows editor starts with EF BB BF: before a row and before a
  // comment; the row keeps its line number.
  const std::string row = write("bom-row.txt",
                                "\xEF\xBB\xBF"
                                "0.1 2.5\n0.4 3\n");
  const auto a = read_period_table(row, "the test table", "'T v'");
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].period, 0.1);
  EXPECT_EQ(a[0].value, 2.5);
  EXPECT_EQ(a[0].where, row + ":1");
  const std::string comment = write("bom-comment.txt", "\xEF\xBB\xBF# T v\n0.1 2.5\n");
  const auto b = read_period_table(comment, "the test table", "'T v'");
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].where, comment + ":2");
}

TEST(PeriodTable, ErrorsNameTheFileTheLineAndWhatIsValid) {
  const std::string missing = test::process_scratch_dir() / "missing.txt";
  EXPECT_EQ(error_of(missing),
            missing + ": cannot open the test table; give an existing, readable file");
  const std::string three = write("three.txt", "0.1 1\n0.2 1 5\n");
  EXPECT_EQ(error_of(three), three + ":2: expected two numbers 'T v'");
  const std::string one = write("one.txt", "0.1\n");
  EXPECT_EQ(error_of(one), one + ":1: expected two numbers 'T v'");
  const std::string down = write("down.txt", "0.5 1\n0.2 1\n");
  EXPECT_EQ(error_of(down), down + ":2: period 0.2 s; valid: > 0 and larger than the previous");
  const std::string zero = write("zero.txt", "0 1\n");
  EXPECT_NE(error_of(zero).find(zero + ":1: period 0 s"), std::string::npos);
  const std::string word = write("word.txt", "0.1 abc\n");
  EXPECT_NE(error_of(word).find(word + ":1"), std::string::npos) << error_of(word);
  EXPECT_NE(error_of(word).find("abc"), std::string::npos) << error_of(word);
}

}  // namespace
}  // namespace pound
