// What every tool and sample does around grass: its name in messages, a failed grass call as an
// error naming the call, the library's log on stderr, files it writes.
#pragma once

#include <grass/grass.h>

#include <stdexcept>
#include <string>

namespace grass_sample {

// A failure that ends the tool's run: main prints "<tool>: <what>" and exits with 1.
struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws a Failure naming `call`, grass_result_string(result) and the context's last error,
// unless result is GRASS_SUCCESS.
void check(grass_result result, const char* call, const grass_context* ctx = nullptr);

// Prints "<tool>: <message>" on stderr; returns 1 (the exit status of a failed run).
int fail(const char* tool, const std::string& message);

// A grass_context_desc.log_fn: "grass <level> <id>: <message>" on stderr.
void GRASS_API_PTR log_to_stderr(void* user_data, grass_log_level level, grass_message_id id, const char* message);

// Creates the directory and its parents (as mkdir -p); false on failure.
bool make_dirs(const std::string& path);
// Writes `text` to the file; false on failure.
bool write_text(const std::string& path, const std::string& text);

} // namespace grass_sample
