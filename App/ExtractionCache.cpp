// SPDX-License-Identifier: LGPL-2.1-or-later
#include "ExtractionCache.h"

#include <algorithm>
#include <chrono>
#include <list>
#include <memory>
#include <mutex>
#include <string_view>

#include "ExtractionParameters.h"

namespace FeatureLines {

using featurelines::CloudGeometry;
using featurelines::ExtractionOptions;
using featurelines::PointMatrix;
using featurelines::RegionAnalysis;

namespace {

/// A small most-recently-used list: lookups are linear, there are two or three entries.
template <class Value> class RecentlyUsed
{
public:
    std::shared_ptr<const Value> find(const std::string& key)
    {
        for (auto it = entries.begin(); it != entries.end(); ++it) {
            if (it->first == key) {
                entries.splice(entries.begin(), entries, it);
                return entries.front().second;
            }
        }
        return nullptr;
    }
    void insert(const std::string& key, std::shared_ptr<const Value> value, int capacity)
    {
        entries.emplace_front(key, std::move(value));
        trim(capacity);
    }
    void trim(int capacity)
    {
        while (static_cast<int>(entries.size()) > capacity) {
            entries.pop_back();
        }
    }
    void clear() { entries.clear(); }
    int size() const { return static_cast<int>(entries.size()); }

private:
    std::list<std::pair<std::string, std::shared_ptr<const Value>>> entries;
};

struct Cache
{
    /// Guards everything below: a task panel analyses in a worker thread while the document
    /// may recompute in the GUI thread. Held only to look up or store, never while the core runs.
    std::mutex mutex;
    RecentlyUsed<CloudGeometry> geometry;
    RecentlyUsed<RegionAnalysis> analysis;
    CacheStatistics statistics;
    int capacity = 2;
};

Cache& cache()
{
    static Cache instance;
    return instance;
}

class CoreTimer
{
public:
    explicit CoreTimer(double& total) : total(total), start(std::chrono::steady_clock::now()) {}
    ~CoreTimer()
    {
        total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

private:
    double& total;
    std::chrono::steady_clock::time_point start;
};

std::string geometryKey(std::uint64_t cloudHash, const ExtractionOptions& options)
{
    return std::to_string(cloudHash) + ';' + stageKey(options, ParameterStage::Cloud);
}

std::shared_ptr<const CloudGeometry> findOrAnalyseCloud(const PointMatrix& P,
                                                        const std::string& key,
                                                        const ExtractionOptions& options,
                                                        double& coreSeconds)
{
    Cache& c = cache();
    {
        std::lock_guard<std::mutex> lock(c.mutex);
        if (auto hit = c.geometry.find(key)) {
            ++c.statistics.geometryHits;
            return hit;
        }
        ++c.statistics.geometryMisses;
    }
    std::shared_ptr<const CloudGeometry> g;
    {
        CoreTimer timer(coreSeconds);
        g = std::make_shared<const CloudGeometry>(featurelines::analyseCloud(
            P, options.neighbours, options.progress, options.progressInterval));
    }
    std::lock_guard<std::mutex> lock(c.mutex);
    c.geometry.insert(key, g, c.capacity);
    return g;
}

CloudAnalysis analyse(const PointMatrix& P, std::uint64_t cloudHash,
                      const ExtractionOptions& options, double& coreSeconds)
{
    Cache& c = cache();
    const std::string cloudKey = geometryKey(cloudHash, options);
    CloudAnalysis a;
    a.geometry = findOrAnalyseCloud(P, cloudKey, options, coreSeconds);

    const std::string regionsKey = cloudKey + '|' + stageKey(options, ParameterStage::Regions);
    {
        std::lock_guard<std::mutex> lock(c.mutex);
        a.regions = c.analysis.find(regionsKey);
        if (a.regions) {
            ++c.statistics.analysisHits;
            return a;
        }
        ++c.statistics.analysisMisses;
    }
    {
        CoreTimer timer(coreSeconds);
        a.regions = std::make_shared<const RegionAnalysis>(
            featurelines::analyseRegions(*a.geometry, options));
    }
    std::lock_guard<std::mutex> lock(c.mutex);
    c.analysis.insert(regionsKey, a.regions, c.capacity);
    return a;
}

} // namespace

std::uint64_t hashCloud(const PointMatrix& P)
{
    const std::string_view bytes(reinterpret_cast<const char*>(P.data()),
                                 static_cast<size_t>(P.size()) * sizeof(double));
    return std::hash<std::string_view>{}(bytes) ^ (static_cast<std::uint64_t>(P.rows()) << 1);
}

featurelines::ExtractionResult extractCached(const PointMatrix& P, std::uint64_t cloudHash,
                                             const ExtractionOptions& options)
{
    double coreSeconds = 0.0;
    const CloudAnalysis a = analyse(P, cloudHash, options, coreSeconds);
    featurelines::ExtractionResult result;
    {
        CoreTimer timer(coreSeconds);
        result = featurelines::extractFeatureLines(*a.geometry, *a.regions, options);
    }
    Cache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    c.statistics.lastCoreSeconds = coreSeconds;
    return result;
}

CloudAnalysis analyseCached(const PointMatrix& P, std::uint64_t cloudHash,
                            const ExtractionOptions& options)
{
    double coreSeconds = 0.0;
    return analyse(P, cloudHash, options, coreSeconds);
}

std::shared_ptr<const CloudGeometry> geometryCached(const PointMatrix& P, std::uint64_t cloudHash,
                                                    const featurelines::NeighbourOptions& options)
{
    ExtractionOptions all;
    all.neighbours = options;
    double coreSeconds = 0.0;
    return findOrAnalyseCloud(P, geometryKey(cloudHash, all), all, coreSeconds);
}

CacheStatistics cacheStatistics()
{
    Cache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    CacheStatistics s = c.statistics;
    s.geometryEntries = c.geometry.size();
    s.analysisEntries = c.analysis.size();
    s.capacity = c.capacity;
    return s;
}

void clearCache()
{
    Cache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    c.geometry.clear();
    c.analysis.clear();
    c.statistics = CacheStatistics{};
}

void setCacheCapacity(int entries)
{
    Cache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    c.capacity = std::max(0, entries);
    c.geometry.trim(c.capacity);
    c.analysis.trim(c.capacity);
}

} // namespace FeatureLines
