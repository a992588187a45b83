/* A C host passes enums by value: C lets it pass any int (fuzz_api_sequence found grass
 * loading them as C++ enums, undefined behaviour that UBSan reports). */
#include <grass/grass.h>

const char* c_host_result_string(int result) { return grass_result_string((grass_result)result); }

grass_quality_desc c_host_quality_preset(int level) { return grass_quality_preset((grass_quality_level)level); }
