#include "app/temporal_error.h"

#include <algorithm>

#include "render/readback.h"

namespace planet {

std::vector<std::size_t> refinedPixels(const Renderer& r, glm::ivec2 size) {
    std::vector<std::size_t> marked;
    // (A still frame lists the pixels whose surface changed under the anti-aliasing's jitter for their
    // spatial estimate, not for a march: render/sky_refine.comp's STILL_FRAME program.)
    if (!r.lastPrepare().reducedRate || r.lastPrepare().stillFrame) return marked;
    for (glm::ivec2 p : r.targets().readSkyRefineList())
        marked.push_back(std::size_t(size.y - 1 - p.y) * std::size_t(size.x) + std::size_t(p.x));  // row 0 the top
    std::sort(marked.begin(), marked.end());
    return marked;
}

std::vector<TemporalFrameError> measureTemporalError(Renderer& temporal, Renderer& fullRate, Session& session,
                                                     const CameraPath& path, int frameCount, int first, int last,
                                                     glm::ivec2 size, TemporalWorstFrame* worst,
                                                     const std::function<void(const TemporalFrameError&)>& progress) {
    const double clockStart = session.scene.time_s;
    std::vector<TemporalFrameError> errors;
    for (int i = first; i < last; ++i) {
        const double t = pathFrameTime(path.file(), i, frameCount);
        applyPathSample(path, t, clockStart, session);
        Scene reference = session.scene;
        reference.render.temporal = false;
        temporal.render(session.scene, session.camera, size);
        fullRate.render(reference, session.camera, size);
        ImageRGBAF a = readTextureRGBAF(temporal.targets().hdr(), size.x, size.y);
        ImageRGBAF b = readTextureRGBAF(fullRate.targets().hdr(), size.x, size.y);
        const ImageComparison c = compareImages(a, b);
        TemporalFrameError e;
        e.frame = i;
        e.time_s = t - path.file().startTime();
        e.meanRelative = c.meanRelativeError;
        e.p99Relative = c.errorPercentile(99.0);
        e.maxRelative = c.maxRelativeError;
        e.reducedRate = temporal.lastPrepare().reducedRate;
        e.refinedShare = static_cast<double>(refinedPixels(temporal, size).size()) / (double(size.x) * size.y);
        errors.push_back(e);
        if (worst && (worst->temporal.pixels.empty() || e.p99Relative > worst->error.p99Relative))
            *worst = {e, std::move(a), std::move(b)};
        if (progress) progress(e);
    }
    session.scene.time_s = clockStart;
    return errors;
}

}  // namespace planet
