// libFuzzer target: CF time units and calendars as a file may hold them.
// The input is "units\0calendar\0value".
#include <cstdlib>
#include <string>

#include "gen/readers/cf_time.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string in(reinterpret_cast<const char*>(data), size);
    const size_t a = in.find('\0'), b = a == std::string::npos ? a : in.find('\0', a + 1);
    const std::string units = in.substr(0, a);
    const std::string calendar = a == std::string::npos ? "" : in.substr(a + 1, b == std::string::npos ? b : b - a - 1);
    const double value = b == std::string::npos ? 0.0 : std::atof(in.c_str() + b + 1);
    const std::string date = tsf::cfDate(units, calendar, value);
    if (date.size() > 64) __builtin_trap();  // a date, never more
    return 0;
}
