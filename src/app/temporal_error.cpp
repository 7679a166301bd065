#include "app/temporal_error.h"

#include "render/readback.h"

namespace planet {

namespace {

// The share of the frame's pixels that the reconstruction marked for a full-rate march.
double refinedShare(const Renderer& r, glm::ivec2 size) {
    if (!r.lastPrepare().reducedRate) return 0.0;
    const ImageRGBA8 mask = readTextureRGBA8(r.targets().skyRefine(), size.x, size.y);
    std::size_t marked = 0;
    for (std::size_t i = 0; i < mask.pixels.size(); i += 4) marked += mask.pixels[i] > 127 ? 1 : 0;
    return static_cast<double>(marked) / (static_cast<double>(size.x) * size.y);
}

}  // namespace

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
        e.refinedShare = refinedShare(temporal, size);
        errors.push_back(e);
        if (worst && (worst->temporal.pixels.empty() || e.p99Relative > worst->error.p99Relative))
            *worst = {e, std::move(a), std::move(b)};
        if (progress) progress(e);
    }
    session.scene.time_s = clockStart;
    return errors;
}

}  // namespace planet
