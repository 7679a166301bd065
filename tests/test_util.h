// Small helpers shared by several test files.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "scene/toml_error.h"

namespace planet::test {

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Runs f, expecting an InputError; returns it for inspection.
inline InputError expectInputError(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "expected an InputError";
    return InputError("", 0, "", "none thrown");
}

}  // namespace planet::test
