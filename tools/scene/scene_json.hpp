// The scene files' JSON reading (tools/scene/scene.cpp, responsive_scene.cpp): every key
// named by its path from the top ("field.maps.density", "colliders[2].centre"), numbers
// checked against what their field can hold, keys checked against a list, values shown in
// messages cut short (never a whole array or a 64 MB string), each refusal naming the key.
#pragma once

#include "file_bytes.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace grass_sample::scene_json {

using nlohmann::json;

// A value for a message, at most about 80 characters: a number or a string (cut), an array
// or object's first members with nested ones as [...] and {...}. Never recurses: a value
// nested thousands deep is shown as "[[...]]".
inline std::string shown(const json& v) {
    auto scalar = [](const json& s) {
        if (s.is_string())
            return json(cut(s.get_ref<const std::string&>())).dump(-1, ' ', false, json::error_handler_t::replace);
        if (s.is_array()) return std::string(s.empty() ? "[]" : "[...]");
        if (s.is_object()) return std::string(s.empty() ? "{}" : "{...}");
        return s.dump();
    };
    if (!v.is_structured()) return scalar(v);
    std::string text = v.is_array() ? "[" : "{";
    bool first = true;
    for (auto it = v.begin(); it != v.end() && text.size() <= 80; ++it) {
        if (!first) text += ",";
        first = false;
        if (v.is_object()) text += json(cut(it.key(), 40)).dump(-1, ' ', false, json::error_handler_t::replace) + ":";
        text += scalar(*it);
    }
    return cut(text) + (v.is_array() ? "]" : "}");
}

// The path of `key` under `where` ("" is the file's top level).
inline std::string join(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
}
inline std::string quoted(const std::string& path) { return "\"" + cut(path) + "\""; }

// `v` when it is an object; otherwise refused naming `path`.
inline const json& object_at(const json& v, const std::string& path) {
    if (!v.is_object()) {
        throw std::runtime_error((path.empty() ? std::string("the scene") : quoted(path)) + " must be an object, not " +
                                 shown(v));
    }
    return v;
}

// `v` when it is an array; otherwise refused naming `path`.
inline const json& array_at(const json& v, const std::string& path, const char* of) {
    if (!v.is_array()) throw std::runtime_error(quoted(path) + " must be a list of " + of + ", not " + shown(v));
    return v;
}

// A JSON number as T, refused by name when T cannot hold it (nlohmann's get<T> converts with a
// plain cast: 1e308 into an unsigned or a float is undefined behaviour, found by fuzz_scene).
template <class T>
T number_as(const json& v, const std::string& what) {
    if (!v.is_number()) throw std::runtime_error(what + " must be a number, not " + shown(v));
    auto refuse = [&]() -> T { throw std::runtime_error(what + " is " + shown(v) + ", out of range"); };
    if constexpr (std::is_integral_v<T>) {
        using L = std::numeric_limits<T>;
        if (v.is_number_float()) {
            const double d = v.get<double>();
            // [min, 2^digits): exact bounds in double for every integer type used here.
            const double top = std::ldexp(1.0, L::digits);
            if (!(d == std::floor(d)) || d < static_cast<double>(L::lowest()) || !(d < top)) return refuse();
            return static_cast<T>(d);
        }
        if (v.is_number_unsigned()) {
            const uint64_t u = v.get<uint64_t>();
            if (u > static_cast<uint64_t>(L::max())) return refuse();
            return static_cast<T>(u);
        }
        const int64_t i = v.get<int64_t>();
        if constexpr (std::is_unsigned_v<T>) {
            if (i < 0 || static_cast<uint64_t>(i) > static_cast<uint64_t>(L::max())) return refuse();
        } else {
            if (i < static_cast<int64_t>(L::lowest()) || i > static_cast<int64_t>(L::max())) return refuse();
        }
        return static_cast<T>(i);
    } else {
        const double d = v.get<double>();
        if (!(std::fabs(d) <= static_cast<double>(std::numeric_limits<T>::max()))) return refuse(); // NaN too
        return static_cast<T>(d);
    }
}

// j[key] (a number, or a boolean for bool) into *out when j has the key; `where` is j's path.
template <class T>
void read(const json& j, const std::string& where, const char* key, T* out) {
    if (!j.contains(key)) return;
    const json& v = j.at(key);
    const std::string name = quoted(join(where, key));
    if constexpr (std::is_same_v<T, bool>) {
        if (!v.is_boolean()) throw std::runtime_error(name + " must be true or false, not " + shown(v));
        *out = v.get<bool>();
    } else {
        *out = number_as<T>(v, name);
    }
}

// A JSON array of numbers as T, each checked as number_as does.
template <class T>
std::vector<T> numbers_as(const json& v, const std::string& what) {
    if (!v.is_array()) throw std::runtime_error(what + " must be an array of numbers, not " + shown(v));
    std::vector<T> out;
    for (const json& e : v) out.push_back(number_as<T>(e, what));
    return out;
}

template <class T>
void read3(const json& j, const std::string& where, const char* key, T out[3]) {
    if (!j.contains(key)) return;
    const std::string name = quoted(join(where, key));
    const auto v = numbers_as<T>(j.at(key), name);
    if (v.size() != 3) throw std::runtime_error(name + " must have 3 numbers, not " + shown(j.at(key)));
    for (int k = 0; k < 3; ++k) out[k] = v[k];
}

// j[key] as a string, or `fallback` when j has no such key.
inline std::string text_of(const json& j, const std::string& where, const char* key, const char* fallback = "") {
    if (!j.contains(key)) return fallback;
    const json& v = j.at(key);
    if (!v.is_string()) throw std::runtime_error(quoted(join(where, key)) + " must be a string, not " + shown(v));
    return v.get<std::string>();
}

// Refuses a non-object or a key not in `allowed`, naming `where`.
inline void check_keys(const json& j, const std::string& where, std::initializer_list<const char*> allowed) {
    object_at(j, where);
    for (auto it = j.begin(); it != j.end(); ++it) {
        bool known = false;
        for (const char* a : allowed) known = known || it.key() == a;
        if (!known) {
            throw std::runtime_error("unknown key \"" + cut(it.key()) + "\" in " +
                                     (where.empty() ? std::string("the scene") : quoted(where)));
        }
    }
}

} // namespace grass_sample::scene_json
