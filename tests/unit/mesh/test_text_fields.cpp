// The numbers of fixed-column text files as other tools write them (mesh/raw_mesh.hpp
// text_mesh): Fortran exponents with D, with no letter at all (2.00000-3), and integers written
// as reals (7.0000000), which LS-DYNA reads alike.
#include <gtest/gtest.h>

#include "fpmshell/mesh/raw_mesh.hpp"

namespace fpmshell {
namespace {

using text_mesh::parse_real;
using text_mesh::parse_whole;

TEST(TextFields, ReadsRealsAsFortranWritesThem) {
    Real v = 0;
    ASSERT_TRUE(parse_real("2.00000-3", v));
    EXPECT_EQ(v, 2.0e-3);
    ASSERT_TRUE(parse_real(" -1.5+10 ", v));
    EXPECT_EQ(v, -1.5e10);
    ASSERT_TRUE(parse_real("1.0D+3", v));
    EXPECT_EQ(v, 1.0e3);
    ASSERT_TRUE(parse_real("7.", v));
    EXPECT_EQ(v, 7.0);
    ASSERT_TRUE(parse_real("-0.5", v));  // a leading sign is the number's own
    EXPECT_EQ(v, -0.5);
    // not numbers: a sign with nothing after it, two exponents, letters
    EXPECT_FALSE(parse_real("1.0-", v));
    EXPECT_FALSE(parse_real("1.0e-3-2", v));
    EXPECT_FALSE(parse_real("abc", v));
    EXPECT_FALSE(parse_real("1.0-3-2", v));
}

TEST(TextFields, ReadsWholeNumbersAlsoWrittenAsReals) {
    long long n = 0;
    ASSERT_TRUE(parse_whole("7", n));
    EXPECT_EQ(n, 7);
    ASSERT_TRUE(parse_whole("7.0000000", n));
    EXPECT_EQ(n, 7);
    ASSERT_TRUE(parse_whole("1.2E+3", n));
    EXPECT_EQ(n, 1200);
    EXPECT_FALSE(parse_whole("7.5", n));
    EXPECT_FALSE(parse_whole("1e20", n));  // beyond what an id can be
    EXPECT_FALSE(parse_whole("", n));
}

}  // namespace
}  // namespace fpmshell
