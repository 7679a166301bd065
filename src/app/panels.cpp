#include "app/panels.h"

#include <imgui.h>
#include <imgui_internal.h>  // FindWindowByName

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/render_scale.h"
#include "ocean/ocean_gpu.h"
#include "ocean/ocean_params_table.h"
#include "ocean/wave_spectrum.h"
#include "scene/preset_waves.h"
#include "scene/scene_params.h"

namespace planet {

namespace {

void statsRow(const char* name, const RollingStats& gpu, const RollingStats& cpu, const RollingStats& wait) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    for (double v : {gpu.min(), gpu.median(), gpu.max(), cpu.median(), cpu.max(), wait.median()}) {
        ImGui::TableNextColumn();
        if (std::isnan(v)) ImGui::TextDisabled("-");
        else ImGui::Text("%.3f", v);
    }
}

void historyGraph(const char* label, const RollingStats& stats) {
    const std::vector<double> history = stats.history();
    std::vector<float> values(history.begin(), history.end());
    const float top = values.empty() ? 1.0f : *std::max_element(values.begin(), values.end()) * 1.2f;
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s  median %.2f ms", label, stats.median());
    ImGui::PlotLines("##graph", values.data(), static_cast<int>(values.size()), 0, overlay, 0.0f, std::max(top, 0.1f),
                     ImVec2(ImGui::GetContentRegionAvail().x, 70.0f));
}

// Drag speed per pixel: half a percent of the value, so coefficients of 5e-6 and
// radii of 6360 both tune smoothly; a floor keeps zero values movable.
float dragSpeed(const ParamSpec& spec, double magnitude) {
    return static_cast<float>(std::max(magnitude * 5e-3, (spec.max - spec.min) * 1e-7));
}

bool paramWidget(const ParamSpec& spec, Scene& scene) {
    const std::string label = spec.key + (spec.unit.empty() ? "" : " [" + spec.unit + "]");
    const ParamRef ref = spec.field(scene);
    bool changed = false;
    if (auto* d = std::get_if<double*>(&ref)) {
        const float speed = dragSpeed(spec, std::abs(**d));
        changed = ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, *d, speed, &spec.min, &spec.max, "%.6g",
                                    ImGuiSliderFlags_AlwaysClamp);
    } else if (auto* i = std::get_if<int*>(&ref)) {
        changed = ImGui::SliderInt(label.c_str(), *i, static_cast<int>(spec.min), static_cast<int>(spec.max));
    } else if (auto* v = std::get_if<glm::dvec3*>(&ref)) {
        if (spec.min == 0.0 && spec.max == 1.0) {
            float c[3] = {float((**v).x), float((**v).y), float((**v).z)};
            changed = ImGui::ColorEdit3(label.c_str(), c, ImGuiColorEditFlags_Float);
            if (changed) **v = glm::clamp(glm::dvec3(c[0], c[1], c[2]), 0.0, 1.0);
        } else {
            const float speed = dragSpeed(spec, glm::max(std::abs((**v).x), glm::max(std::abs((**v).y), std::abs((**v).z))));
            changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_Double, &(**v).x, 3, speed, &spec.min,
                                         &spec.max, "%.5g", ImGuiSliderFlags_AlwaysClamp);
        }
    } else if (auto* b = std::get_if<bool*>(&ref)) {
        changed = ImGui::Checkbox(label.c_str(), *b);
    }
    if (ImGui::IsItemHovered() && !spec.help.empty()) ImGui::SetTooltip("%s", spec.help.c_str());
    return changed;
}

// The first-use placement of the panel `name` (initialPanelLayout), for the next Begin.
void placeOnFirstUse(const char* name) {
    if (ImGui::FindWindowByName(name)) return;  // placed already: nothing to do on later frames
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    for (const PanelPlacement& p : initialPanelLayout(display.x, display.y)) {
        if (p.name != name) continue;
        ImGui::SetNextWindowPos(ImVec2(p.x, p.y), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(p.width, p.height), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowCollapsed(p.collapsed, ImGuiCond_FirstUseEver);
    }
}

}  // namespace

std::vector<PanelPlacement> initialPanelLayout(float w, float h) {
    const float right = std::max(w - 330.0f, 0.0f);
    return {{"Frame time", 10.0f, 10.0f, 430.0f, std::min(260.0f, 0.4f * h), false},
            {"Scene", 10.0f, std::min(280.0f, 0.5f * h), 560.0f, std::min(420.0f, 0.55f * h), true},
            {"Camera", right, 10.0f, 320.0f, std::min(330.0f, 0.5f * h), true},
            {"Waves", right, 40.0f, 320.0f, std::min(360.0f, 0.5f * h), true}};
}

double panelCoverage(const std::vector<PanelPlacement>& layout, float w, float h, float titleHeight) {
    // Counted on the pixel grid, so overlaps count once.
    const int width = std::max(static_cast<int>(w), 1), height = std::max(static_cast<int>(h), 1);
    std::vector<unsigned char> covered(static_cast<std::size_t>(width) * height, 0);
    for (const PanelPlacement& p : layout) {
        const float bottom = p.y + (p.collapsed ? titleHeight : p.height);
        for (int y = std::max(static_cast<int>(p.y), 0); y < std::min(static_cast<int>(bottom), height); ++y)
            for (int x = std::max(static_cast<int>(p.x), 0); x < std::min(static_cast<int>(p.x + p.width), width); ++x)
                covered[static_cast<std::size_t>(y) * width + x] = 1;
    }
    std::size_t count = 0;
    for (unsigned char c : covered) count += c;
    return static_cast<double>(count) / static_cast<double>(covered.size());
}

namespace {

// A slider for the share of the window rendered (each new size restarts the frame's
// history), and a button back to auto.
void renderScaleRow(RenderScaleUi& scale) {
    float value = static_cast<float>(scale.effective);
    ImGui::SetNextItemWidth(140.0f);
    if (ImGui::SliderFloat("render scale", &value, static_cast<float>(kMinRenderScale), 1.0f, "%.2f"))
        scale.chosen = std::clamp(static_cast<double>(value), kMinRenderScale, 1.0);
    ImGui::SameLine();
    ImGui::TextDisabled("%dx%d%s", scale.frame.x, scale.frame.y, scale.chosen ? "" : " (auto)");
    if (scale.chosen) {
        ImGui::SameLine();
        if (ImGui::SmallButton("auto")) scale.chosen.reset();
    }
}

}  // namespace

void drawProfilerPanel(Profiler& profiler, const std::string& renderer, RenderScaleUi* scale) {
    placeOnFirstUse("Frame time");
    if (!ImGui::Begin("Frame time")) return ImGui::End();
    if (scale) renderScaleRow(*scale);
    const double cpu = profiler.frameCpuMs().median();
    ImGui::Text("%.1f FPS   frame CPU %.2f ms   waited %.2f ms   GPU %.2f ms", ImGui::GetIO().Framerate, cpu,
                profiler.frameWaitMs().median(), profiler.frameGpuMs().median());
    ImGui::TextDisabled("%s", renderer.c_str());
    if (softwareRenderer(renderer)) ImGui::TextWrapped("%s", softwareTimingNote());
    bool finish = profiler.finishEachPass();
    if (ImGui::Checkbox("finish each pass", &finish)) profiler.setFinishEachPass(finish);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Wait for the GPU before and after each pass (glFinish), so that a pass's CPU + wait is "
                          "its own work and nothing of the passes before it. On by default on a software renderer; "
                          "on a GPU it stops the passes overlapping and slows the frame.");
    historyGraph("GPU", profiler.frameGpuMs());
    // CPU: the pass's own CPU time (submitting); wait: the rest of its wall time, off the CPU
    // (mostly the driver waiting for earlier GPU work).
    if (ImGui::BeginTable("passes", 7, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        for (const char* h : {"pass", "GPU min", "med", "max", "CPU med", "max", "wait med"}) ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        for (const PassTimings& p : profiler.passes()) statsRow(p.name.c_str(), p.gpuMs, p.cpuMs, p.waitMs);
        statsRow("frame", profiler.frameGpuMs(), profiler.frameCpuMs(), profiler.frameWaitMs());
        ImGui::EndTable();
    }
    if (profiler.droppedFrames() > 0)
        ImGui::TextDisabled("%lld frames without GPU timings (GPU too far behind)", profiler.droppedFrames());
    ImGui::End();
}

bool drawSceneParams(Scene& scene, double rebuildProgress, double cloudBakeProgress, const char* rebuildLabel) {
    placeOnFirstUse("Scene");
    bool changed = false;
    if (!ImGui::Begin("Scene")) {
        ImGui::End();
        return false;
    }
    ImGui::PushItemWidth(-260.0f);  // room for the longest label with its unit
    std::string section;
    bool open = false;
    for (const ParamSpec& spec : sceneParams()) {
        if (spec.section != section) {
            section = spec.section;
            open = ImGui::CollapsingHeader(section.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
            if (open && section == "atmosphere" && rebuildProgress < 1.0)
                ImGui::ProgressBar(static_cast<float>(rebuildProgress), ImVec2(-1.0f, 0.0f), rebuildLabel);
            if (open && section == "clouds" && cloudBakeProgress < 1.0)
                ImGui::ProgressBar(static_cast<float>(cloudBakeProgress), ImVec2(-1.0f, 0.0f),
                                   "baking the cloud volume and weather map");
        }
        if (!open) continue;
        ImGui::PushID(spec.path().c_str());
        if (paramWidget(spec, scene)) {
            changed = true;
            // The wave set follows its generator's parameters (edits in the Waves panel are replaced).
            if (isWaveGeneratorParam(spec)) scene.waves = ocean::generateWaves(scene.ocean);
        }
        ImGui::PopID();
    }
    ImGui::PopItemWidth();
    ImGui::End();
    return changed;
}

CameraPanelResult drawCameraPanel(const Camera& camera, CameraController& controller, Scene& scene,
                                  const std::vector<View>& views, std::string& presetPath, const std::string& status) {
    CameraPanelResult result;
    placeOnFirstUse("Camera");
    if (!ImGui::Begin("Camera")) {
        ImGui::End();
        return result;
    }
    const double altitude = camera.altitude(scene.planetRadiusM());
    const glm::dvec3 up = glm::normalize(camera.position);
    ImGui::Text("altitude %.3f %s", altitude >= 1e4 ? altitude / 1e3 : altitude, altitude >= 1e4 ? "km" : "m");
    ImGui::Text("lat %.4f  lon %.4f", glm::degrees(std::asin(glm::clamp(up.z, -1.0, 1.0))),
                glm::degrees(std::atan2(up.y, up.x)));
    int mode = controller.mode == CameraMode::Fly ? 0 : 1;
    if (ImGui::RadioButton("fly", mode == 0)) controller.mode = CameraMode::Fly;
    ImGui::SameLine();
    if (ImGui::RadioButton("orbit", mode == 1)) controller.mode = CameraMode::Orbit;
    ImGui::SameLine();
    ImGui::TextDisabled("(Tab)");
    float speed = static_cast<float>(controller.speedScale);
    if (ImGui::SliderFloat("speed", &speed, 1e-3f, 1e3f, "%.3g", ImGuiSliderFlags_Logarithmic))
        controller.speedScale = speed;
    // The planet turns under the sun: one drag goes from dawn over noon to dusk here.
    float hour = static_cast<float>(localSolarHour(scene.sun, up));
    if (ImGui::SliderFloat("time of day", &hour, 0.0f, 24.0f, "%.2f h")) {
        setLocalSolarHour(scene.sun, up, hour);
        result.sunMoved = true;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Local solar time at the camera: moves the sun's longitude (its latitude, the season, stays)");
    ImGui::Separator();
    ImGui::TextUnformatted("Views (keys 1-9)");
    for (std::size_t i = 0; i < views.size(); ++i) {
        if (i % 4 != 0) ImGui::SameLine();
        if (ImGui::Button(views[i].name.c_str())) result.jumpToView = static_cast<int>(i);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", views[i].description.c_str());
    }
    ImGui::Separator();
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "%s", presetPath.c_str());
    if (ImGui::InputText("##preset", buffer, sizeof buffer)) presetPath = buffer;
    ImGui::SameLine();
    result.savePreset = ImGui::Button("Save preset");
    if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
    ImGui::End();
    return result;
}

namespace {

// One wave's fields; the origin as latitude and longitude. True when one changed.
bool waveWidgets(ocean::GerstnerWave& w) {
    bool changed = false;
    double lat = glm::degrees(std::asin(glm::clamp(w.origin.z, -1.0, 1.0)));
    double lon = glm::degrees(std::atan2(w.origin.y, w.origin.x));
    const double latRange[2] = {-90.0, 90.0}, lonRange[2] = {-180.0, 180.0};
    // Both widgets are drawn every frame; either moving changes the origin.
    const bool latChanged = ImGui::DragScalar("origin lat [deg]", ImGuiDataType_Double, &lat, 0.05f, &latRange[0],
                                              &latRange[1], "%.4f", ImGuiSliderFlags_AlwaysClamp);
    const bool lonChanged = ImGui::DragScalar("origin lon [deg]", ImGuiDataType_Double, &lon, 0.05f, &lonRange[0],
                                              &lonRange[1], "%.4f", ImGuiSliderFlags_AlwaysClamp);
    if (latChanged || lonChanged) {
        w.origin = directionFromLatLon(lat, lon);
        changed = true;
    }
    for (const WaveField& f : waveFields()) {
        double& value = w.*f.member;
        const bool onDispersion = f.member == &ocean::GerstnerWave::wavelength_m &&
                                  std::abs(w.speed_mps - ocean::deepWaterSpeed(w.wavelength_m)) <= 1e-9 * w.speed_mps;
        const std::string label = std::string(f.key) + (f.unit[0] ? std::string(" [") + f.unit + "]" : std::string());
        const float speed = static_cast<float>(std::max(std::abs(value) * 5e-3, 1e-4));
        if (ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &value, speed, &f.lo, &f.hi, "%.5g",
                              ImGuiSliderFlags_AlwaysClamp)) {
            changed = true;
            // A wave on the deep-water dispersion relation stays on it; a custom speed is kept.
            if (onDispersion) w.speed_mps = ocean::deepWaterSpeed(w.wavelength_m);
        }
    }
    return changed;
}

}  // namespace

bool drawWavePanel(Scene& scene, WaveClock& clock) {
    placeOnFirstUse("Waves");
    if (!ImGui::Begin("Waves")) {
        ImGui::End();
        return false;
    }
    bool changed = false;
    ImGui::Text("t = %.2f s", scene.time_s);
    ImGui::SameLine();
    ImGui::Checkbox("pause", &clock.paused);
    float rate = static_cast<float>(clock.rate);
    if (ImGui::SliderFloat("time rate", &rate, 0.01f, 100.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) clock.rate = rate;
    ImGui::Text("%zu waves, H_s %.2f m, max crest %.2f m", scene.waves.size(),
                ocean::significantWaveHeight(scene.waves), ocean::maxWaveHeight(scene.waves));
    if (ImGui::Button("Regenerate from [ocean]")) {
        scene.waves = ocean::generateWaves(scene.ocean);
        changed = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Add wave")) {
        ocean::GerstnerWave w;
        w.origin = directionFromLatLon(scene.ocean.wind_latitude_deg, scene.ocean.wind_longitude_deg);
        w.speed_mps = ocean::deepWaterSpeed(w.wavelength_m);
        scene.waves.push_back(w);
        changed = true;
    }
    ImGui::PushItemWidth(-130.0f);
    const std::size_t shown = std::min<std::size_t>(scene.waves.size(), 256);  // a list of 4096 is not browsable
    for (std::size_t i = 0; i < shown; ++i) {
        ImGui::PushID(static_cast<int>(i));
        char title[96];
        std::snprintf(title, sizeof title, "wave %zu: %.3g m long, amplitude %.3g m", i, scene.waves[i].wavelength_m,
                      scene.waves[i].amplitude_m);
        if (ImGui::TreeNode(title)) {
            changed |= waveWidgets(scene.waves[i]);
            if (ImGui::Button("Remove")) {
                scene.waves.erase(scene.waves.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
                ImGui::TreePop();
                ImGui::PopID();
                break;
            }
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (shown < scene.waves.size()) ImGui::TextDisabled("(first %zu of %zu shown)", shown, scene.waves.size());
    ImGui::PopItemWidth();
    ImGui::End();
    return changed;
}

void drawShaderErrors(const std::vector<std::string>& errors) {
    if (errors.empty()) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y - 10), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowSize(ImVec2(display.x * 0.8f, 0), ImGuiCond_Always);
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.35f, 0.02f, 0.02f, 0.92f));
    ImGui::Begin("Shader error (last good program still in use)", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    for (const std::string& e : errors) ImGui::TextWrapped("%s", e.c_str());
    ImGui::End();
    ImGui::PopStyleColor();
}

void drawStatusLine(const std::string& text, double progress) {
    if (text.empty()) return;
    // Bottom right, out of the way of the panels' starting places and of the shader errors (bottom centre).
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x - 10, display.y - 10), ImGuiCond_Always, ImVec2(1.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("##status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
    ImGui::TextUnformatted(text.c_str());
    if (progress >= 0.0) ImGui::ProgressBar(static_cast<float>(progress), ImVec2(260.0f, 0.0f));
    ImGui::End();
}

}  // namespace planet
