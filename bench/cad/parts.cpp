// SPDX-License-Identifier: LGPL-2.1-or-later
// featurelines_parts: lists the random parts of seeds (PartFamilies.h) with their family,
// faces, typed edges and drawn parameters; writes a part as BREP, or a shaded picture of its
// sampled points with the true edges drawn on top (sharp red, smooth blue, boundary green).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <BRepTools.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <Eigen/Geometry>

#include "PartFamilies.h"
#include "ShapeSampling.h"

using namespace featurelines;
using namespace featurelines::bench;

namespace {

const char* usage =
    "usage: featurelines_parts [options]\n"
    "  --seeds A-B         seeds A to B (default 0-15); --seeds N for one\n"
    "  --points N          fix the target point count (default: drawn, 10 000 to 1 000 000)\n"
    "  --parameters        print every drawn parameter under each part\n"
    "  --brep DIR          write DIR/part-<seed>-<family>.brep\n"
    "  --image DIR         write DIR/part-<seed>-<family>.ppm: the part sampled at about\n"
    "                      --image-points points (default 40000), shaded, true edges on top\n";

struct Arguments
{
    std::uint32_t first = 0;
    std::uint32_t last = 15;
    double points = 0.0;
    bool parameters = false;
    std::string brepDir;
    std::string imageDir;
    double imagePoints = 40000.0;
};

Arguments parse(int argc, char** argv)
{
    Arguments a;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                throw std::invalid_argument(arg + " needs a value");
            }
            return argv[++i];
        };
        if (arg == "--seeds") {
            const std::string v = value();
            const size_t dash = v.find('-');
            a.first = static_cast<std::uint32_t>(std::stoul(v.substr(0, dash)));
            a.last = dash == std::string::npos
                         ? a.first
                         : static_cast<std::uint32_t>(std::stoul(v.substr(dash + 1)));
        } else if (arg == "--points") {
            a.points = std::stod(value());
        } else if (arg == "--parameters") {
            a.parameters = true;
        } else if (arg == "--brep") {
            a.brepDir = value();
        } else if (arg == "--image") {
            a.imageDir = value();
        } else if (arg == "--image-points") {
            a.imagePoints = std::stod(value());
        } else {
            throw std::invalid_argument("unknown option " + arg);
        }
    }
    if (a.last < a.first) {
        throw std::invalid_argument("--seeds A-B needs A <= B");
    }
    return a;
}

int countOf(const TopoDS_Shape& shape, TopAbs_ShapeEnum type)
{
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, type, map);
    return map.Extent();
}

/// An orthographic view from the front right above, the sampled points as shaded discs in a
/// depth buffer, the true edges' samples drawn over the visible surface.
void writePicture(const std::string& file, const SampledCloud& cloud,
                  const std::vector<TypedPolyline>& truth, double spacing)
{
    const int width = 900;
    const int height = 700;
    const Eigen::Vector3d view = Eigen::Vector3d(1.0, -1.4, 1.0).normalized(); // toward eye
    const Eigen::Vector3d right = Eigen::Vector3d::UnitZ().cross(view).normalized();
    const Eigen::Vector3d up = view.cross(right);
    const Eigen::Vector3d light = (view + 0.5 * up + 0.3 * right).normalized();
    double minX = std::numeric_limits<double>::max(), maxX = -minX, minY = minX, maxY = -minX;
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        const Eigen::Vector3d p = cloud.points.row(i).transpose();
        minX = std::min(minX, p.dot(right));
        maxX = std::max(maxX, p.dot(right));
        minY = std::min(minY, p.dot(up));
        maxY = std::max(maxY, p.dot(up));
    }
    const double scale = 0.92 * std::min(width / (maxX - minX), height / (maxY - minY));
    const double cx = 0.5 * (minX + maxX), cy = 0.5 * (minY + maxY);
    std::vector<double> depth(static_cast<size_t>(width * height),
                              -std::numeric_limits<double>::max());
    std::vector<unsigned char> rgb(static_cast<size_t>(3 * width * height), 255);
    const auto pixel = [&](const Eigen::Vector3d& p, int& x, int& y) {
        x = static_cast<int>(std::lround(0.5 * width + scale * (p.dot(right) - cx)));
        y = static_cast<int>(std::lround(0.5 * height - scale * (p.dot(up) - cy)));
    };
    const int splat = std::max(1, static_cast<int>(std::ceil(0.7 * spacing * scale)));
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        const Eigen::Vector3d p = cloud.points.row(i).transpose();
        const Eigen::Vector3d n = cloud.normals.row(i).transpose();
        // Both sides of an open sheet are lit alike.
        const double shade = 0.2 + 0.8 * std::abs(n.dot(light));
        int x0, y0;
        pixel(p, x0, y0);
        for (int dy = -splat; dy <= splat; ++dy) {
            for (int dx = -splat; dx <= splat; ++dx) {
                const int x = x0 + dx, y = y0 + dy;
                if (x < 0 || y < 0 || x >= width || y >= height ||
                    dx * dx + dy * dy > splat * splat) {
                    continue;
                }
                const size_t k = static_cast<size_t>(y * width + x);
                if (p.dot(view) > depth[k]) {
                    depth[k] = p.dot(view);
                    const auto g = static_cast<unsigned char>(std::lround(235.0 * shade));
                    rgb[3 * k] = g;
                    rgb[3 * k + 1] = g;
                    rgb[3 * k + 2] = g;
                }
            }
        }
    }
    const unsigned char colours[3][3] = {{220, 30, 30}, {30, 80, 230}, {20, 170, 40}};
    for (const TypedPolyline& line : truth) {
        const unsigned char* c = colours[static_cast<int>(line.type)];
        for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
            const Eigen::Vector3d p = line.points.row(i).transpose();
            int x0, y0;
            pixel(p, x0, y0);
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int x = x0 + dx, y = y0 + dy;
                    if (x < 0 || y < 0 || x >= width || y >= height) {
                        continue;
                    }
                    const size_t k = static_cast<size_t>(y * width + x);
                    // Hidden edges (behind the surface by more than two spacings) stay hidden.
                    if (p.dot(view) < depth[k] - 2.0 * spacing) {
                        continue;
                    }
                    std::copy(c, c + 3, rgb.begin() + static_cast<long>(3 * k));
                }
            }
        }
    }
    std::ofstream out(file, std::ios::binary);
    out << "P6\n" << width << " " << height << "\n255\n";
    out.write(reinterpret_cast<const char*>(rgb.data()), static_cast<std::streamsize>(rgb.size()));
    if (!out) {
        throw std::runtime_error("could not write " + file);
    }
}

} // namespace

int main(int argc, char** argv)
{
    Arguments args;
    try {
        args = parse(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n" << usage;
        return 2;
    }
    RandomPartOptions options;
    options.points = args.points;
    std::printf("| seed | family | target points | faces | edges | sharp | smooth | boundary | "
                "min radius | fallbacks |\n|---|---|---|---|---|---|---|---|---|---|\n");
    int failures = 0;
    for (std::uint32_t seed = args.first; seed <= args.last; ++seed) {
        try {
            const RandomPart part = makeRandomPart(seed, options);
            TruthOptions truthOptions;
            truthOptions.step = 0.5 * part.spacing;
            const auto truth = truthEdges(part.shape, truthOptions);
            int counts[lineTypeCount] = {0, 0, 0};
            for (const TypedPolyline& l : truth) {
                ++counts[static_cast<int>(l.type)];
            }
            std::printf("| %u | %s | %.0f | %d | %d | %d | %d | %d | %.3g | %s |\n", seed,
                        part.familyName.c_str(), part.targetPoints,
                        countOf(part.shape, TopAbs_FACE), countOf(part.shape, TopAbs_EDGE),
                        counts[0], counts[1], counts[2], part.smallestRadius,
                        part.fallbacks.empty() ? "-" : part.fallbacks.c_str());
            if (args.parameters) {
                std::printf("    %s\n", part.parameters.c_str());
            }
            std::fflush(stdout);
            const std::string stem = "part-" + std::to_string(seed) + "-" + part.familyName;
            if (!args.brepDir.empty()) {
                const std::string file = args.brepDir + "/" + stem + ".brep";
                if (!BRepTools::Write(part.shape, file.c_str())) {
                    throw std::runtime_error("could not write " + file);
                }
            }
            if (!args.imageDir.empty()) {
                SamplingOptions sampling;
                sampling.radius = radiusForPointCount(shapeArea(part.shape), args.imagePoints);
                sampling.seed = seed;
                const SampledCloud cloud = sampleShape(part.shape, sampling);
                const double spacing = meanNearestSpacing(cloud.points);
                truthOptions.step = 0.5 * spacing;
                writePicture(args.imageDir + "/" + stem + ".ppm", cloud,
                             truthEdges(part.shape, truthOptions), spacing);
            }
        } catch (const std::exception& e) {
            std::fprintf(stderr, "seed %u: %s\n", seed, e.what());
            ++failures;
        }
    }
    return failures == 0 ? 0 : 1;
}
