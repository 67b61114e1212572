// SPDX-License-Identifier: LGPL-2.1-or-later
// The feature lines in the featurelines tool's lines file: one JSON object per line.
#pragma once

#include <string>

#include "FeatureLines/Extraction.h"
#include "FeatureLines/cli/Json.h"

namespace featurelines::cli {

/// One line: its type, ends, angle (sharp) and blend radius (smooth), null where not
/// estimated, a smooth line's region and threshold, and its points.
inline std::string lineJson(const FeatureLine& l)
{
    using namespace json;
    Object line;
    line.add("type", string(lineTypeName(l.type)))
        .add("closed", l.closed ? "true" : "false")
        .add("start_junction", number(static_cast<long>(l.startJunction)))
        .add("end_junction", number(static_cast<long>(l.endJunction)))
        .add("angle", number(l.angle))
        .add("blend_radius", number(l.blendRadius));
    if (l.type == LineType::Smooth) {
        line.add("region", number(static_cast<long>(l.region)))
            .add("threshold", number(l.threshold));
    }
    line.add("points", json::points(l.points));
    return line.str();
}

/// The lines of the result as a JSON array, one line per row.
inline std::string linesJson(const ExtractionResult& r)
{
    std::string lines = "[";
    for (std::size_t i = 0; i < r.lines.size(); ++i) {
        lines += (i ? ",\n  " : "\n  ") + lineJson(r.lines[i]);
    }
    return lines + "\n]";
}

} // namespace featurelines::cli
