// SPDX-License-Identifier: LGPL-2.1-or-later
// Fuzz entry points of the readers: the bytes of a file as the reader of one format sees
// them (FUZZ_FORMAT: ".xyz", ".ply" or ".pcd", set by CMakeLists.txt). A refusal is a
// std::invalid_argument; anything else (another exception, a crash, a sanitizer report, a
// hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "FeatureLines/io/CloudFormats.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try {
        featurelines::detail::parseCloud(
            std::string_view(reinterpret_cast<const char*>(data), size), "fuzz" FUZZ_FORMAT);
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
