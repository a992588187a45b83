// The scene files' JSON reading (samples/common/scene.cpp, responsive_scene.cpp): numbers
// checked against what their field can hold, keys checked against a list, each refused by name.
#pragma once

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

// A JSON number as T, refused by name when T cannot hold it (nlohmann's get<T> converts with a
// plain cast: 1e308 into an unsigned or a float is undefined behaviour, found by fuzz_scene).
template <class T>
T number_as(const json& v, const std::string& what) {
    if (!v.is_number()) throw std::runtime_error(what + " must be a number, not " + v.dump());
    auto refuse = [&]() -> T { throw std::runtime_error(what + " is " + v.dump() + ", out of range"); };
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
        if (std::fabs(d) > static_cast<double>(std::numeric_limits<T>::max())) return refuse();
        return static_cast<T>(d);
    }
}

template <class T>
void read(const json& j, const char* key, T* out) {
    if (!j.contains(key)) return;
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
        *out = number_as<T>(j.at(key), std::string("\"") + key + "\"");
    } else {
        *out = j.at(key).get<T>();
    }
}

// A JSON array of numbers as T, each checked as number_as does.
template <class T>
std::vector<T> numbers_as(const json& v, const std::string& what) {
    if (!v.is_array()) throw std::runtime_error(what + " must be an array of numbers, not " + v.dump());
    std::vector<T> out;
    for (const json& e : v) out.push_back(number_as<T>(e, what));
    return out;
}

template <class T>
void read3(const json& j, const char* key, T out[3]) {
    if (!j.contains(key)) return;
    const auto v = numbers_as<T>(j.at(key), std::string("\"") + key + "\"");
    if (v.size() != 3) throw std::runtime_error(std::string("\"") + key + "\" must have 3 numbers");
    for (int k = 0; k < 3; ++k) out[k] = v[k];
}
inline void check_keys(const json& j, const char* where, std::initializer_list<const char*> allowed) {
    for (auto it = j.begin(); it != j.end(); ++it) {
        bool known = false;
        for (const char* a : allowed) known = known || it.key() == a;
        if (!known) throw std::runtime_error(std::string("unknown key \"") + it.key() + "\" in " + where);
    }
}

} // namespace grass_sample::scene_json
