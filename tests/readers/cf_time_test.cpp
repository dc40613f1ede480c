// CF time coordinates as dates (gen/readers/cf_time.h): the units and
// calendars climate files use, and what it refuses to guess.
#include <gtest/gtest.h>

#include <cmath>

#include "gen/readers/cf_time.h"

namespace tsf {
namespace {

TEST(CfTime, StandardCalendarsGiveTheDate) {
    EXPECT_EQ(cfDate("days since 1850-01-01", "standard", 59), "1850-03-01");  // 1850 is no leap year
    EXPECT_EQ(cfDate("days since 2000-01-01", "gregorian", 60), "2000-03-01");  // 2000 is
    EXPECT_EQ(cfDate("days since 1900-01-01", "proleptic_gregorian", 59), "1900-03-01");  // 1900 is not
    EXPECT_EQ(cfDate("days since 2000-01-01", "", 31), "2000-02-01");  // no calendar: the standard one
    EXPECT_EQ(cfDate("hours since 1970-01-01 00:00:00", "standard", 36), "1970-01-02 12:00");
    EXPECT_EQ(cfDate("minutes since 2020-12-31T23:00", "standard", 90), "2021-01-01 00:30");
    EXPECT_EQ(cfDate("seconds since 1970-01-01", "standard", 86400 * 365), "1971-01-01");
    EXPECT_EQ(cfDate("days since 2000-01-01", "standard", -1), "1999-12-31");
    EXPECT_EQ(cfDate("days since 1-1-1", "standard", 0), "0001-01-01");
}

TEST(CfTime, WhatItCannotSayIsLeftAsTheNumber) {
    EXPECT_EQ(cfDate("days since 2000-01-01", "noleap", 59), "");
    EXPECT_EQ(cfDate("days since 2000-01-01", "360_day", 59), "");
    EXPECT_EQ(cfDate("months since 2000-01-01", "standard", 2), "");  // not a fixed length
    EXPECT_EQ(cfDate("days", "standard", 2), "");
    EXPECT_EQ(cfDate("days since yesterday", "standard", 2), "");
    EXPECT_EQ(cfDate("days since 2000-13-01", "standard", 2), "");
    EXPECT_EQ(cfDate("days since 2000-01-01", "standard", NAN), "");
    EXPECT_EQ(cfDate("days since 2000-01-01", "standard", 1e300), "");
    EXPECT_EQ(cfDate("days since 99999999999-01-01", "standard", 0), "");
}

}  // namespace
}  // namespace tsf
