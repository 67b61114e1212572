// SPDX-License-Identifier: LGPL-2.1-or-later
// Just enough JSON output for the featurelines tool: strings, numbers, arrays of numbers and
// of points.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "FeatureLines/PointCloud.h"
#include "FeatureLines/cli/Arguments.h"

namespace featurelines::cli::json {

/// A JSON string literal: quotes, backslash and control characters escaped.
inline std::string string(const std::string& s)
{
    std::string out = "\"";
    for (const char c : s) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\t':
            out += "\\t";
            break;
        case '\r':
            out += "\\r";
            break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char buffer[8];
                std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
                out += buffer;
            } else {
                out += c;
            }
        }
    }
    return out + "\"";
}

/// A JSON number that reads back to the same double (JSON has no NaN or infinity: null).
inline std::string number(double v)
{
    return std::isfinite(v) ? Arguments::format(v) : std::string("null");
}

inline std::string number(long v)
{
    return std::to_string(v);
}

template <typename T> std::string array(const std::vector<T>& values)
{
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        out += (i ? ", " : "") + number(values[i]);
    }
    return out + "]";
}

/// A point as [x, y, z].
inline std::string point(const Eigen::Vector3d& p)
{
    return "[" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + "]";
}

/// The rows of P as an array of points.
inline std::string points(const PointMatrix& P)
{
    std::string out = "[";
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        out += (i ? ", " : "") + point(P.row(i).transpose());
    }
    return out + "]";
}

/// A JSON object written in the order its members are added; values are JSON text already.
class Object
{
public:
    Object& add(const std::string& key, const std::string& jsonValue)
    {
        text_ += (text_.empty() ? "" : ", ") + string(key) + ": " + jsonValue;
        return *this;
    }
    std::string str() const { return "{" + text_ + "}"; }

private:
    std::string text_;
};

} // namespace featurelines::cli::json
