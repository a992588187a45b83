/* The C side of fuzz_api_sequence. The fuzzed lod test callback: it answers from the fuzzer's bytes, mostly real answers,
 * sometimes values no grass_lod_answer has. Written in C, as a host's callback may be: a C
 * function may return any int as an enum (C++ may not even form such a value). */
#ifndef GRASS_FUZZ_LOD_CALLBACK_H
#define GRASS_FUZZ_LOD_CALLBACK_H

#include <grass/grass.h>

#ifdef __cplusplus
#    include <cstddef>
namespace grass_fuzz {
extern "C" {
#endif

typedef struct Answers {
    const unsigned char* bytes; /* what the callback answers, in turn */
    size_t size;
    size_t next;
} Answers;

grass_lod_answer garbage_answer(void* user, const grass_lod_node* node);

/* The calls that take an enum by value, given any int (as a C host may). */
grass_quality_desc fuzz_quality_preset(int level);
const char* fuzz_result_string(int result);

#ifdef __cplusplus
}
} /* namespace grass_fuzz */
#endif

#endif
