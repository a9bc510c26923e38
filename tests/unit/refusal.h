// SPDX-License-Identifier: Apache-2.0
// Shared by the unit tests of every layer: the message of the enteron::Error a call throws,
// its code checked, so that a table of bad inputs compares whole messages.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "base/error.h"

namespace unit_test {

// What `call()` throws: its message, after checking its code; "(no refusal)" if it
// returns.
template <class Call>
std::string refusal(Call call, enteron::ErrorCode code = enteron::ErrorCode::invalid_argument) {
    try {
        call();
    } catch (const enteron::Error& error) {
        EXPECT_EQ(error.code(), code) << error.what();
        return error.what();
    }
    return "(no refusal)";
}

}  // namespace unit_test
