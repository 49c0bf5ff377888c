// A Radiant scene as a RADIANCE scene (Ward 1994), so that the two programs can be compared on
// the same room: the geometry Radiant solves, its materials and emitters in RADIANCE's units, and
// the sensor points as rtrace -I input. RADIANCE itself is not needed to write the files.
#pragma once

#include <cstddef>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "radiant/scene.h"

namespace radiant::radiance {

/// RADIANCE's luminous efficacy of its radiometric unit (lm/W): radiance, irradiance and
/// exitance in RADIANCE are photometric quantities divided by 179 (rtrace's -I output times 179
/// is lux; Radiant's lm/m² are divided by 179 on the way in).
inline constexpr double kLumensPerWatt = 179.0;

struct ExportOptions {
    /// Radius (m) of the small sphere or disk standing for each point luminaire. Outside it an
    /// isotropic sphere's field is exactly a point's; a disk's differs by O((r/d)²).
    double source_radius_m = 0.01;
    /// When > 0, also writes surface-points.txt and surface-samples.txt: about this many
    /// area-weighted points on each surface, for surface averages (Radiant's average_irradiance).
    int surface_samples = 0;
    /// Surfaces to sample (by name); empty: all.
    std::vector<std::string> sample_surfaces;
    /// Data-file resolution of photometric luminaires (degrees in C; γ is sampled 4 times finer,
    /// 20 times for a table alike in every C-plane, whose file is over γ alone).
    double photometric_step_deg = 1.0;
};

/// A contiguous run of lines of points.txt: one of the scene's sensor sets.
struct PointRange {
    std::string name;
    std::size_t first = 0, count = 0;
};

/// One surface's points in surface-points.txt; `weights_m2` (the area each point stands for)
/// sum to the surface's area.
struct SurfaceSamples {
    std::string name;
    int surface = 0;  ///< index in the scene's surfaces
    std::size_t first = 0;
    std::vector<double> weights_m2;
    Rgb reflectance{0, 0, 0};     ///< of the surface's material (front side)
    Rgb exitance_lm_m2{0, 0, 0};  ///< emitted from the front
};

struct ExportSummary {
    int channels = 1;           ///< 1 for gray scenes, 3 for RGB (as Radiant solves them)
    std::size_t materials = 0;  ///< RADIANCE materials written (modifiers, patterns excluded)
    std::size_t polygons = 0;
    std::size_t light_sources = 0;  ///< emitting polygons plus point luminaires
    /// Emitting polygons. rtrace cuts a source into parts (-ds) only for rays of high weight;
    /// the shadow rays of reflected rays aim at the whole source's centre unless jittered
    /// (-dj 1), which lights a wall near a large panel as if the panel were a point.
    std::size_t area_sources = 0;
    /// Emitters that also reflect are a light behind a partly transparent reflecting layer.
    /// rtrace must then test every shadow ray (-dt 0): it adds the sources it does not test at
    /// their unoccluded value, which for these lights is 1/(1 − c) too bright.
    bool needs_all_shadow_tests = false;
    std::vector<PointRange> sensors;
    std::size_t points = 0;  ///< lines of points.txt
    std::vector<SurfaceSamples> surfaces;
    std::size_t surface_points = 0;
};

struct ExportOutcome {
    bool ok = false;
    std::string error;  ///< why nothing (or not everything) was written
    ExportSummary summary;
};

/// Writes DIR/scene.rad, DIR/points.txt (`x y z nx ny nz` per sensor point, in metres, in the
/// order Radiant reports them), DIR/README (the rtrace command line), a data file per
/// photometric luminaire and, when asked, the surface samples. `scene` must have passed
/// check_scene() and expand_workplanes() (as proto::load_scene_file returns it). Geometry is the
/// engine's prepared scene: in metres, world frame, every surface as convex polygons. Creates
/// DIR. Thread-safe for distinct directories.
ExportOutcome write_radiance_scene(const Scene& scene, const std::filesystem::path& dir,
                                   const ExportOptions& options = {});

/// Reads rtrace -I output (three radiometric irradiances, W/m², per line, no header) and
/// returns each line's three channels in lux (× 179): the converter gives RADIANCE's channels
/// Radiant's values one for one. Stops at the first malformed line; the caller compares the
/// count with the number of points.
std::vector<Rgb> irradiance_from_rtrace(std::istream& rtrace_output);

/// Radiant's photometric value of a colour (Rec. 709 weights, as Radiant reports RGB sensors
/// and surfaces) — not rtrace's own 0.265/0.670/0.065.
double photometric(const Rgb& c);

struct SurfaceAverages {
    double irradiance_lux = 0;   ///< Radiant's average_irradiance (front side)
    double radiosity_lm_m2 = 0;  ///< Radiant's average_radiosity: ρ·E + M, front side
};

/// Area-weighted averages over a surface from `irradiance_lux` (one entry per line of
/// surface-points.txt); NaN when lines are missing.
SurfaceAverages surface_average(const SurfaceSamples& samples,
                                const std::vector<Rgb>& irradiance_lux);

}  // namespace radiant::radiance
