// How far the temporal march (render.temporal) strays from the full-rate march along a camera
// path: every frame rendered twice, by a renderer that keeps its history from frame to frame
// (as the explorer and `planet render --path` do) and by one that marches every pixel, and
// compared in linear luminance (render/image_compare.h). `planet bench --suite temporal` runs
// it over a whole path; tests/test_temporal.cpp over a stretch of one.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "app/camera_path.h"
#include "app/session.h"
#include "render/image_compare.h"
#include "render/image_io.h"
#include "render/renderer.h"

namespace planet {

struct TemporalFrameError {
    int frame = 0;              // index in the sequence
    double time_s = 0.0;        // along the path, from its start
    double meanRelative = 0.0;  // mean relative luminance error (image_compare.h, floor 1 % of the mean)
    double p99Relative = 0.0;   // its 99th percentile
    double maxRelative = 0.0;
    bool reducedRate = false;   // the temporal frame was marched at the reduced rate
    double refinedShare = 0.0;  // the share of its pixels marched again at full rate ("sky refine")
};

// The two images of the worst frame (highest 99th percentile) seen so far, for a caller that
// writes them out.
struct TemporalWorstFrame {
    TemporalFrameError error;
    ImageRGBAF temporal, fullRate;
};

// The pixels the reconstruction of the renderer's last frame marked for a full-rate march
// (render/sky_refine.comp), as indices into an image read by readTextureRGBAF (row 0 at the
// top); none where that frame was not marched at the reduced rate.
std::vector<std::size_t> refinedPixels(const Renderer& r, glm::ivec2 size);

// Frames [first, last) of a sequence of `frameCount` frames along `path` (pathFrameTime),
// at `size`. `temporal` renders with the session's scene (render.temporal on) and keeps its
// history across the frames; `fullRate` renders the same frames with render.temporal off.
// `progress`, when given, is called after each frame.
std::vector<TemporalFrameError> measureTemporalError(Renderer& temporal, Renderer& fullRate, Session& session,
                                                     const CameraPath& path, int frameCount, int first, int last,
                                                     glm::ivec2 size, TemporalWorstFrame* worst = nullptr,
                                                     const std::function<void(const TemporalFrameError&)>& progress = {});

}  // namespace planet
