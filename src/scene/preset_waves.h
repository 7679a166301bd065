// The preset's list of individual ocean waves, [[ocean.wave]] (see preset.h):
//
//     [[ocean.wave]]
//     origin = [0.0, 0.0, 1.0]   # unit vector where the wave starts (or latitude_deg + longitude_deg)
//     amplitude_m = 0.4
//     wavelength_m = 30.0
//     steepness = 0.3            # Q, [0, 1]
//     speed_mps = 6.84           # optional: deep-water dispersion sqrt(g / k) when absent
//     phase_rad = 0.0            # optional
//
// A preset with such a list uses exactly those waves; one without generates them
// from the [ocean] parameters (ocean/wave_spectrum.h). `wave = []` under [ocean] is
// an empty list: no waves at all (what a preset saved with every wave removed holds).
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "ocean/waves.h"

namespace planet {

// A wave's scalar fields with the ranges a preset may give them; the explorer's Waves
// panel draws one widget per entry, so the two always agree.
struct WaveField {
    const char* key;  // TOML key, e.g. "amplitude_m"
    double lo, hi;    // inclusive range
    const char* unit;
    double ocean::GerstnerWave::*member;
};
const std::vector<WaveField>& waveFields();

// Reads the list at node (the value of ocean.wave). Throws InputError naming file,
// line and field (e.g. "ocean.wave[2].steepness") for a bad entry.
std::vector<ocean::GerstnerWave> readWaveList(const toml::node& node, const std::string& file);

// The list as TOML text: one [[ocean.wave]] table per wave, every field written.
std::string waveListToToml(const std::vector<ocean::GerstnerWave>& waves);

// True when two wave lists are identical field for field.
bool sameWaves(const std::vector<ocean::GerstnerWave>& a, const std::vector<ocean::GerstnerWave>& b);

}  // namespace planet
