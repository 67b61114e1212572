// SPDX-License-Identifier: LGPL-2.1-or-later
// The extraction with its two expensive shared steps cached (Extraction.h: analyseCloud ->
// CloudGeometry, analyseRegions -> RegionAnalysis), so that changing a threshold re-runs only
// the last step. One cache per process: the document objects and the Python functions share it,
// so a macro trying thresholds on a cloud a document object already analysed reuses that work.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "FeatureLines/Extraction.h"

namespace FeatureLines {

/// Identity of a cloud's content: a hash of its coordinates and of the point count.
std::uint64_t hashCloud(const featurelines::PointMatrix& P);

/// Runs the extraction of P (whose content hash is `cloudHash`) through the cache:
/// analyseCloud when no entry has this cloud and neighbour count, analyseRegions when no entry
/// has also the same parameters of the Regions stage (ExtractionParameters.h), then
/// extractFeatureLines. Throws what the core throws (std::invalid_argument,
/// featurelines::ExtractionCancelled from options.progress).
featurelines::ExtractionResult extractCached(const featurelines::PointMatrix& P,
                                             std::uint64_t cloudHash,
                                             const featurelines::ExtractionOptions& options);

/// The two cached steps of an extraction (Extraction.h): what extractCached runs before the last
/// step, which thresholds the regions. Held by shared pointer, so a holder keeps an entry the
/// cache has since dropped.
struct CloudAnalysis
{
    std::shared_ptr<const featurelines::CloudGeometry> geometry;
    std::shared_ptr<const featurelines::RegionAnalysis> regions;
};

/// analyseCloud and analyseRegions of P through the cache, as extractCached runs them: for a
/// task panel that analyses in a worker thread (the cache is guarded by a mutex, held while an
/// entry is looked up or stored, not while the core runs) and then previews thresholds of the
/// regions before the document object recomputes with a warm cache. Throws what the core
/// throws.
CloudAnalysis analyseCached(const featurelines::PointMatrix& P, std::uint64_t cloudHash,
                            const featurelines::ExtractionOptions& options);

/// Neighbours, spacing and normals of P through the same cache (for curvature histograms of a
/// whole cloud).
std::shared_ptr<const featurelines::CloudGeometry>
geometryCached(const featurelines::PointMatrix& P, std::uint64_t cloudHash,
               const featurelines::NeighbourOptions& options);

struct CacheStatistics
{
    long geometryHits = 0;
    long geometryMisses = 0;
    long analysisHits = 0;
    long analysisMisses = 0;
    int geometryEntries = 0;
    int analysisEntries = 0;
    int capacity = 0;
    /// Seconds spent in the core library by the last extraction (cached steps cost nothing).
    double lastCoreSeconds = 0.0;
};

CacheStatistics cacheStatistics();
/// Drops every entry and resets the counters.
void clearCache();
/// Entries kept of each kind, the most recently used first (default 2: a cloud of a million
/// points costs about half a gigabyte per pair of entries). 0 disables caching.
void setCacheCapacity(int entries);

} // namespace FeatureLines
