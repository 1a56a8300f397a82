// The list-option parser of common/app/cli.hpp (--dims, --sizes, ...): sorted, deduplicated,
// decimal digits only, every value in range, and a message that names the flag.

#include "app/cli.hpp"

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

constexpr auto parse_int_list = &mcrt::parse_list<int>;

namespace {

using Ints = std::vector<int>;

// The message of the error parse_int_list throws, or "" when it accepts the text.
std::string rejection(const std::string& text, int lowest = 0, int highest = 100) {
  try {
    parse_int_list(text, "--dims", lowest, highest);
  } catch (const CLI::ValidationError& e) {
    return e.what();
  }
  return "";
}

TEST(ParseIntListTest, SortsAndRemovesDuplicates) {
  EXPECT_EQ(parse_int_list("3,1,2", "--dims", 1, 10), (Ints{1, 2, 3}));
  EXPECT_EQ(parse_int_list("5,5,1,5", "--dims", 1, 10), (Ints{1, 5}));
  EXPECT_EQ(parse_int_list("7", "--dims", 1, 10), (Ints{7}));
}

TEST(ParseIntListTest, TheBoundsAreInclusive) {
  EXPECT_EQ(parse_int_list("1,10", "--dims", 1, 10), (Ints{1, 10}));
  EXPECT_EQ(parse_int_list("0", "--dims", 0, 0), (Ints{0}));
}

TEST(ParseIntListTest, LeadingZerosAreReadAsDecimal) {
  // "010" is ten, not octal eight.
  EXPECT_EQ(parse_int_list("010,08", "--dims", 1, 100), (Ints{8, 10}));
}

TEST(ParseIntListTest, EmptyItemsAreRejected) {
  for (const char* text : {"", "1,,2", ",1", "1,", ","})
    EXPECT_NE(rejection(text), "") << "'" << text << "'";
}

TEST(ParseIntListTest, AnythingButDecimalDigitsIsRejected) {
  for (const char* text : {"0x10", "-1", "+1", " 1", "1 ", "1.5", "1e2", "a", "1;2"})
    EXPECT_NE(rejection(text), "") << "'" << text << "'";
}

TEST(ParseIntListTest, OutOfRangeIsRejectedNamingTheFlag) {
  const std::string above = rejection("1,101");
  EXPECT_NE(above.find("--dims"), std::string::npos) << above;
  EXPECT_NE(above.find("101"), std::string::npos) << above;
  EXPECT_NE(rejection("4", 5, 9).find("--dims"), std::string::npos);
  // More digits than an int holds: rejected too, never an overflow.
  EXPECT_NE(rejection("99999999999999999999").find("--dims"), std::string::npos);
}

TEST(ParseIntListTest, EveryRejectionNamesTheFlag) {
  for (const char* text : {"", "1,,2", "0x10", "-1", "1000"})
    EXPECT_NE(rejection(text).find("--dims"), std::string::npos) << "'" << text << "'";
}

TEST(AddListOptionTest, TheOptionParsesIntoTheVectorAndKeepsItsDefault) {
  Ints dims{2, 3};
  CLI::App app;
  mcrt::add_list_option(app, "--dims", dims, "dimensions", 1, 12);
  app.parse(std::vector<std::string>{});
  EXPECT_EQ(dims, (Ints{2, 3}));
  app.parse(std::vector<std::string>{"9,4,4", "--dims"});  // CLI11 takes them reversed
  EXPECT_EQ(dims, (Ints{4, 9}));
  EXPECT_THROW(app.parse(std::vector<std::string>{"13", "--dims"}), CLI::ValidationError);
}

// A list of reals such as --q: parsed, sorted and deduplicated, or rejected naming the flag.
std::string real_rejection(const std::string& text) {
  try {
    mcrt::parse_list<double>(text, "--q", 0.001, 0.999);
  } catch (const CLI::ValidationError& e) {
    return e.what();
  }
  return "";
}

TEST(ParseRealListTest, SortsAndDropsDuplicates) {
  using Reals = std::vector<double>;
  EXPECT_EQ(mcrt::parse_list<double>("0.9,0.5,0.5,5e-1,0.7", "--q", 0.001, 0.999),
            (Reals{0.5, 0.7, 0.9}));
  EXPECT_EQ(mcrt::parse_list<double>("0.001,0.999", "--q", 0.001, 0.999), (Reals{0.001, 0.999}));
}

TEST(ParseRealListTest, RejectsWhatIsNotAFiniteDecimalInRange) {
  for (const char* text : {"", "0.5,,0.7", "nan", "inf", "0x1p-1", " 0.5", "0.5 ", "1", "0", "-0.5",
                           "0.5.5", "abc", "1e999"})
    EXPECT_NE(real_rejection(text).find("--q"), std::string::npos) << "'" << text << "'";
}

}  // namespace
