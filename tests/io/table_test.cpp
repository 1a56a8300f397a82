// The one Table (common/io/table.hpp) every tabular output comes from: the CSV bytes of each
// kind of column, the JSON array of summary.json, the aligned console table, and the mistakes
// it refuses (a cell of the wrong kind, a row of the wrong length, an unknown column).

#include "io/table.hpp"

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

using mcrt::Column;
using mcrt::Table;

namespace {

Table example() {
  Table table({{"n", Column::integer}, {"rmse", Column::real, 6}, {"method", Column::text}});
  table.add_row({10, 0.123456789, "mc"});
  table.add_row({std::uint64_t{18446744073709551615u}, 1e-5, "trapezoid"});
  return table;
}

// printf's %.{digits}g, the semantics `digits` promises.
std::string printf_g(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

TEST(TableTest, CsvHasAHeaderRowThenIntegersInFullRealsToTheirDigitsAndText) {
  EXPECT_EQ(example().csv(),
            "n,rmse,method\n"
            "10,0.123457,mc\n"
            "18446744073709551615,1e-05,trapezoid\n");
}

TEST(TableTest, RealsAreWrittenAsPrintfWouldWithTheColumnsDigits) {
  for (const int digits : {1, 3, 6, 9, 12, 17})
    for (const double x : {0.0, -0.0, 1.0, 0.1, 2.0 / 3.0, 3.14159265358979, 123456789.0, 1e-7,
                           -2.5e300, 1e16, 0.0001234, 99999.5}) {
      Table table({{"x", Column::real, digits}});
      table.add_row({x});
      EXPECT_EQ(table.csv(), "x\n" + printf_g(x, digits) + "\n") << x << " at " << digits;
    }
}

TEST(TableTest, RealColumnsTakeIntegersAndNegativeIntegersStayExact) {
  Table table({{"i", Column::integer}, {"x", Column::real}});
  table.add_row({-9223372036854775807LL - 1, 3});
  EXPECT_EQ(table.csv(), "i,x\n-9223372036854775808,3\n");
  EXPECT_TRUE(table.at(0, "x").is_real());
  EXPECT_EQ(table.numbers("x"), std::vector<double>{3.0});
}

TEST(TableTest, JsonIsAnArrayOfOneObjectPerRowKeysInColumnOrder) {
  const nlohmann::ordered_json json = example().json();
  ASSERT_TRUE(json.is_array());
  ASSERT_EQ(json.size(), 2u);
  EXPECT_EQ(json[0].dump(), R"({"n":10,"rmse":0.123456789,"method":"mc"})");
  EXPECT_EQ(json[1]["n"].get<std::uint64_t>(), 18446744073709551615u);
  EXPECT_EQ(json[1]["method"], "trapezoid");
  EXPECT_EQ(Table({{"x", Column::real}}).json().dump(), "[]");
}

TEST(TableTest, ConsoleAlignsColumnsRightUnderTheirNames) {
  Table table({{"n", Column::integer}, {"estimate", Column::real}, {"name", Column::text}});
  table.add_row({1, 3.14159265, "a"});
  table.add_row({1000, 0.5, "long name"});
  EXPECT_EQ(table.console(),
            "     n  estimate       name\n"
            "     1     3.142          a\n"
            "  1000       0.5  long name\n");
  // `only` picks and orders the columns; `indent` sets the left margin.
  EXPECT_EQ(table.console({"name", "n"}, 0),
            "     name     n\n"
            "        a     1\n"
            "long name  1000\n");
}

TEST(TableTest, WrongKindWrongCountAndUnknownColumnThrow) {
  Table table({{"n", Column::integer}, {"x", Column::real}, {"s", Column::text}});
  EXPECT_THROW(table.add_row({1.5, 2.0, "a"}), std::logic_error);     // a real in an integer column
  EXPECT_THROW(table.add_row({1, "x", "a"}), std::logic_error);       // text in a real column
  EXPECT_THROW(table.add_row({1, 2.0, 3}), std::logic_error);         // an integer in a text column
  EXPECT_THROW(table.add_row({1, 2.0}), std::logic_error);            // too few cells
  EXPECT_THROW(table.add_row({1, 2.0, "a", "b"}), std::logic_error);  // too many
  EXPECT_EQ(table.size(), 0u);
  table.add_row({1, 2.0, "a"});
  EXPECT_THROW(static_cast<void>(table.at(0, "y")), std::out_of_range);
  EXPECT_THROW(static_cast<void>(table.numbers("y")), std::out_of_range);
  EXPECT_THROW(static_cast<void>(table.console({"y"})), std::out_of_range);
  EXPECT_THROW(static_cast<void>(table.numbers("s")), std::logic_error);  // text is no number
  EXPECT_THROW(Table({{"a", Column::real}, {"a", Column::real}}), std::logic_error);
}

}  // namespace
