#include "fuzz_lod_callback.h"

#include <stdlib.h>

grass_lod_answer garbage_answer(void* user, const grass_lod_node* node) {
    Answers* a = (Answers*)user;
    if (!node) abort(); /* grass always passes the node */
    if (a->size == 0) return GRASS_LOD_DISCARD;
    const unsigned char b = a->bytes[a->next++ % a->size];
    if (b < 200) return (grass_lod_answer)(b % 3);
    return (grass_lod_answer)((int)b * 0x01010101);
}

grass_quality_desc fuzz_quality_preset(int level) { return grass_quality_preset((grass_quality_level)level); }

const char* fuzz_result_string(int result) { return grass_result_string((grass_result)result); }
