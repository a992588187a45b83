// Enums a C host passes by value may hold any integer; grass reads them as integers (the
// ASan + UBSan build reports a load of an out-of-range enum). Found by fuzz_api_sequence.
#include <grass/grass.h>

#include <gtest/gtest.h>

#include <string>

extern "C" const char* c_host_result_string(int result);
extern "C" grass_quality_desc c_host_quality_preset(int level);

namespace {

TEST(EnumsByValue, AnyIntegerIsANameOrUnknown) {
    EXPECT_EQ(std::string(c_host_result_string(-5)), "GRASS_ERROR_OUT_OF_MEMORY");
    for (int garbage : {751913202, -100, 1, 0x7fffffff}) {
        EXPECT_EQ(std::string(c_host_result_string(garbage)), "GRASS_ERROR_UNKNOWN") << garbage;
    }
}

TEST(EnumsByValue, AnyIntegerIsAPresetOrARefusedDesc) {
    EXPECT_EQ(c_host_quality_preset(GRASS_QUALITY_LOW).msaa_samples, 1u);
    for (int garbage : {-1, 5, 4242}) {
        const grass_quality_desc q = c_host_quality_preset(garbage);
        EXPECT_EQ(static_cast<int>(q.type), 0) << garbage << ": no type tag, so grass_apply_quality refuses it";
    }
}

} // namespace
