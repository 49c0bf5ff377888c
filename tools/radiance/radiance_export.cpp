#include "radiance_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <system_error>

#include "formfactor/point_polygon.h"
#include "scene/prepared_scene.h"

namespace radiant::radiance {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

// Shortest text that reads back as the same double would be longer than any scene needs; ten
// significant digits keep 0.01 mm at 10 km.
std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

// RADIANCE identifiers are single words; anything else in a Radiant name becomes '_'.
std::string identifier(const std::string& prefix, std::size_t index, const std::string& name) {
    std::string id = prefix + std::to_string(index) + "_";
    for (const char c : name) {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                           (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
        id += plain ? c : '_';
    }
    return id;
}

std::string triple(const Rgb& c) { return num(c[0]) + " " + num(c[1]) + " " + num(c[2]); }
std::string triple(const Vec3& v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }

// The photometric frame of a luminaire from -D, the direction of emission towards the point
// being lit (RADIANCE evaluates a light's pattern on the shadow ray, aimed at the source). γ
// and C as Radiant's luminaire_light.cpp computes them: γ from the nadir `aim`, C from the C0
// axis towards C90, wrapped into [0°, 360°).
constexpr const char* kLuminaireCal =
    "{ radiant_lum.cal (radiant-to-radiance): gamma and C of a Radiant photometric luminaire.\n"
    "  A1-A3: nadir (aim), A4-A6: C0 axis, A7-A9: C90 axis, unit vectors in the world frame. }\n"
    "radiant_clamp(x) : if(x - 1, 1, if(-1 - x, -1, x));\n"
    "radiant_gamma = 180/PI * acos(radiant_clamp(-(Dx*arg(1) + Dy*arg(2) + Dz*arg(3))));\n"
    "radiant_c = mod(180/PI * atan2(-(Dx*arg(7) + Dy*arg(8) + Dz*arg(9)),\n"
    "                               -(Dx*arg(4) + Dy*arg(5) + Dz*arg(6))) + 360, 360);\n";

// Offset (m) of the layer that gives a reflecting emitter its reflection: in front of the light
// by more than RADIANCE's self-intersection tolerance (1e-6) and well behind the point 0.1 mm
// in front of a surface where rtrace -I measures.
constexpr double kLayerOffsetM = 1e-5;
// rtrace lights what a ray of low weight reaches (every ambient sample) from an area source
// taken whole, which misjudges a long one seen from near it: an empty room lit by four LED
// strips 11.4 m long and 5 cm wide, 0.55 m under its ceiling, read 16 % dark on its floor, and
// 1.1 % and 0.8 % with the strips cut into 0.25 m and 0.1 m lengths, within the runs' noise
// (docs/radiance-peer.md, "Long emitting surfaces"). An emitting piece longer than
// this many times its width is written as equal lengths of at most that, in at most
// kMaxEmitterParts of them (a line of light 100 m long and 1 mm wide would be 25 000).
constexpr double kMaxEmitterAspect = 4;
constexpr double kMaxEmitterParts = 256;

// A convex emitting piece cut across its length into parts at most kMaxEmitterAspect times as
// long as it is wide (itself when it is no longer).
std::vector<std::vector<Vec3>> emitter_parts(const Piece& p) {
    // Along its longest edge, as long as the piece reaches that way.
    Vec3 along{};
    double longest = 0;
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
        const Vec3 edge = p.vertices[(k + 1) % p.vertices.size()] - p.vertices[k];
        if (length_squared(edge) > longest * longest) {
            longest = std::sqrt(length_squared(edge));
            along = edge / longest;
        }
    }
    double start = 0, end = 0;
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
        const double x = dot(along, p.vertices[k]);
        start = k == 0 ? x : std::min(start, x);
        end = k == 0 ? x : std::max(end, x);
    }
    const double length = end - start;
    const double width = length > 0 ? p.area_m2 / length : 0;
    if (!(width > 0) || length <= kMaxEmitterAspect * width) return {p.vertices};
    const auto parts = static_cast<int>(
        std::min(std::ceil(length / (kMaxEmitterAspect * width)), kMaxEmitterParts));
    std::vector<std::vector<Vec3>> out;
    for (int k = 0; k < parts; ++k) {
        const Vec3 from = along * (start + length * k / parts);
        const Vec3 to = along * (start + length * (k + 1) / parts);
        std::vector<Vec3> part = clip_to_halfspace(p.vertices, from, along);
        part = clip_to_halfspace(part, to, -along);
        if (part.size() >= 3) out.push_back(std::move(part));
    }
    return out;
}

// What the pieces of one Radiant material are made of in RADIANCE.
struct MaterialIds {
    std::string surface;  ///< the piece itself
    std::string layer;    ///< reflecting emitters: the mixing layer just in front of the light
    std::string back;     ///< two-sided reflecting emitters: the reflector just behind it
};

struct Writer {
    const PreparedScene& scene;
    const ExportOptions& options;
    std::ostringstream rad;
    ExportSummary summary;
    std::vector<MaterialIds> material_ids;
    std::vector<bool> back_in_view;  // per material
    bool black_written = false;

    Vec3 world(const Vec3& local) const { return local + scene.world_origin; }

    // Whether a ray can meet the back of some piece of each one-sided material: only when a ray
    // can start behind its plane, i.e. some piece's vertex or some sensor point lies behind it
    // (convex pieces lie where their vertices do; luminaires only receive shadow rays). Where no
    // back is in view, plain plastic (RADIANCE's own two-sided modelling, and its shadow cache)
    // is exact. Scenes too large to check all pairs are assumed to have backs in view.
    std::vector<bool> backs_in_view() const {
        std::vector<bool> seen(scene.materials.size(), false);
        std::vector<Vec3> origins;
        for (const Piece& p : scene.pieces) {
            origins.insert(origins.end(), p.vertices.begin(), p.vertices.end());
        }
        for (const PreparedSensorSet& set : scene.sensors) {
            for (const Vec3& x : set.points) origins.push_back(x + set.normal * 1.1e-4);
        }
        const double tolerance = 1e-6 * scene.diagonal_m;
        const double budget = 2e8;
        double work = 0;
        for (const Piece& p : scene.pieces) {
            const auto m = static_cast<std::size_t>(p.material);
            if (seen[m] || scene.materials[m].two_sided || scene.materials[m].emits()) continue;
            work += static_cast<double>(origins.size());
            if (work > budget) {
                seen[m] = true;
                continue;
            }
            for (const Vec3& q : origins) {
                if (dot(q - p.vertices[0], p.normal) < -tolerance) {
                    seen[m] = true;
                    break;
                }
            }
        }
        return seen;
    }

    void write_black() {
        if (black_written) return;
        rad << "# the back of one-sided surfaces: black (Radiant reflects nothing there)\n"
            << "void plastic radiant_black\n0\n0\n5 0 0 0 0 0\n\n";
        ++summary.materials;
        black_written = true;
    }

    // A reflector: plastic with the reflectance per channel, no specular part. RADIANCE's
    // surfaces reflect on both sides; a one-sided one whose back is in view mixes to black
    // where Rdot < 0 (the ray meets its back), which keeps it opaque there, as Radiant's backs
    // are. (A mixture is no reliable blocker for rtrace's shadow cache: about 20 % slower.)
    std::string write_reflector(const std::string& id, const PreparedMaterial& m, bool black_back) {
        if (!black_back) {
            rad << "void plastic " << id << "\n0\n0\n5 " << triple(m.reflectance) << " 0 0\n\n";
            ++summary.materials;
            return id;
        }
        write_black();
        rad << "void plastic " << id << "_front\n0\n0\n5 " << triple(m.reflectance) << " 0 0\n"
            << "void mixfunc " << id << "\n4 " << id << "_front radiant_black if(Rdot,1,0) .\n0\n0"
            << "\n\n";
        summary.materials += 2;
        return id;
    }

    // An emitter: Lambertian exitance M (lm/m²) from its front, so radiance M/π (cd/m²), in
    // RADIANCE's unit M/(π·179). A `light` is a source for the direct calculation and black to
    // every other ray (and from behind). RADIANCE has no source that also reflects (an illum's
    // alternate material is hidden from ambient rays), so a reflecting emitter gets a layer just
    // in front of its light: a mixture, coefficient c, of plastic ρ/c and void. Every ray meets
    // c·(plastic ρ/c) — the reflection ρ·E — and passes with weight 1 − c on to the light, whose
    // radiance is raised to L/(1 − c); shadow rays see only the light (plastic blocks them), so
    // they get L. c = (1 + ρmax)/2 keeps ρ/c < 1. A two-sided one also reflects from behind.
    MaterialIds write_emitter(std::size_t i, const PreparedMaterial& m) {
        const std::string id = identifier("m", i, m.name);
        const double rho = std::max({m.reflectance[0], m.reflectance[1], m.reflectance[2]});
        const double c = rho > 0 ? (1 + rho) / 2 : 0;
        Rgb radiance{};
        for (int k = 0; k < 3; ++k) {
            radiance[k] = m.exitance_lm_m2[k] / (kPi * kLumensPerWatt) / (1 - c);
        }
        rad << "void light " << id << "\n0\n0\n3 " << triple(radiance) << "\n";
        ++summary.materials;
        if (!(rho > 0)) {
            rad << '\n';
            return {id, "", ""};
        }
        summary.needs_all_shadow_tests = true;
        const Rgb raised{m.reflectance[0] / c, m.reflectance[1] / c, m.reflectance[2] / c};
        rad << "void plastic " << id << "_reflects\n0\n0\n5 " << triple(raised) << " 0 0\n"
            << "void mixfunc " << id << "_layer\n4 " << id << "_reflects void " << num(c)
            << " .\n0\n0\n";
        summary.materials += 2;
        MaterialIds ids{id, id + "_layer", ""};
        if (m.two_sided) {
            rad << "void plastic " << id << "_back\n0\n0\n5 " << triple(m.reflectance) << " 0 0\n";
            ++summary.materials;
            ids.back = id + "_back";
        }
        rad << '\n';
        return ids;
    }

    void write_materials() {
        back_in_view = backs_in_view();
        rad << "# materials (Radiant reflectance per channel; emitters radiance = exitance / "
               "(pi * 179))\n";
        for (std::size_t i = 0; i < scene.materials.size(); ++i) {
            const PreparedMaterial& m = scene.materials[i];
            material_ids.push_back(
                m.emits() ? write_emitter(i, m)
                          : MaterialIds{write_reflector(identifier("m", i, m.name), m,
                                                        !m.two_sided && back_in_view[i]),
                                        "", ""});
        }
    }

    void write_polygon(const std::string& material, const std::string& id,
                       const std::vector<Vec3>& vertices, const Vec3& shift) {
        rad << material << " polygon " << id << "\n0\n0\n" << 3 * vertices.size() << '\n';
        for (const Vec3& v : vertices) rad << "  " << triple(world(v + shift)) << '\n';
        ++summary.polygons;
    }

    void write_polygons() {
        rad << "# surfaces: the engine's convex pieces, counter-clockwise seen from the front\n";
        std::vector<std::size_t> piece_of_surface(scene.surface_names.size(), 0);
        for (const Piece& p : scene.pieces) {
            const auto s = static_cast<std::size_t>(p.surface);
            const MaterialIds& ids = material_ids[static_cast<std::size_t>(p.material)];
            const bool emits = scene.materials[static_cast<std::size_t>(p.material)].emits();
            for (const std::vector<Vec3>& part :
                 emits ? emitter_parts(p) : std::vector<std::vector<Vec3>>{p.vertices}) {
                const std::string id = identifier("s", s, scene.surface_names[s]) + "." +
                                       std::to_string(piece_of_surface[s]++);
                write_polygon(ids.surface, id, part, {});
                if (!ids.layer.empty())
                    write_polygon(ids.layer, id + ".layer", part, p.normal * kLayerOffsetM);
                if (!ids.back.empty()) {
                    write_polygon(ids.back, id + ".back", {part.rbegin(), part.rend()},
                                  p.normal * -kLayerOffsetM);
                }
                if (emits) {
                    ++summary.light_sources;
                    ++summary.area_sources;
                }
            }
        }
        rad << '\n';
    }

    // Point luminaires: a sphere (isotropic, photometric) or a disk facing `aim` (Lambertian)
    // of radius r whose radiance gives the luminaire's intensity: a sphere shows πr² from every
    // direction, a disk πr²·cos θ.
    bool write_luminaires(const fs::path& dir, std::string& error) {
        if (scene.luminaires.empty()) return true;
        const double r = options.source_radius_m;
        const double projected = kPi * r * r * kLumensPerWatt;
        rad << "# point luminaires (radius " << num(r) << " m)\n";
        bool cal_written = false;
        for (std::size_t i = 0; i < scene.luminaires.size(); ++i) {
            const PreparedLuminaire& l = scene.luminaires[i];
            const std::string id = identifier("l", i, l.name);
            const Vec3 at = world(l.position);
            Rgb radiance{};
            switch (l.distribution) {
                case Distribution::isotropic:
                    for (int k = 0; k < 3; ++k) radiance[k] = l.flux_lm[k] / (4 * kPi) / projected;
                    rad << "void light " << id << "_light\n0\n0\n3 " << triple(radiance) << '\n'
                        << id << "_light sphere " << id << "\n0\n0\n4 " << triple(at) << ' '
                        << num(r) << "\n\n";
                    break;
                case Distribution::lambertian:
                    for (int k = 0; k < 3; ++k) radiance[k] = l.flux_lm[k] / kPi / projected;
                    rad << "void light " << id << "_light\n0\n0\n3 " << triple(radiance) << '\n'
                        << id << "_light ring " << id << "\n0\n0\n8 " << triple(at) << ' '
                        << triple(l.aim) << " 0 " << num(r) << "\n\n";
                    break;
                case Distribution::photometric: {
                    if (!l.table) {
                        error = "luminaire " + l.name + " has no photometric table";
                        return false;
                    }
                    if (!cal_written) {
                        std::ofstream cal(dir / "radiant_lum.cal");
                        cal << kLuminaireCal;
                        if (!cal) {
                            error = "cannot write " + (dir / "radiant_lum.cal").string();
                            return false;
                        }
                        cal_written = true;
                    }
                    const std::string data = id + ".dat";
                    const int dimensions = write_intensity_data(l, dir / data);
                    if (!dimensions) {
                        error = "cannot write " + (dir / data).string();
                        return false;
                    }
                    // The pattern is the table's candela; the light's radiance scales it to the
                    // luminaire's flux and colour.
                    for (int k = 0; k < 3; ++k) {
                        radiance[k] = l.flux_lm[k] / l.table->flux_lm() / projected;
                    }
                    rad << "void brightdata " << id << "_table\n"
                        << 3 + dimensions << " noop ./" << data
                        << " ./radiant_lum.cal radiant_gamma"
                        << (dimensions == 2 ? " radiant_c" : "") << "\n0\n9 " << triple(l.aim)
                        << ' ' << triple(l.c0_axis) << ' ' << triple(l.c90_axis) << '\n'
                        << id << "_table light " << id << "_light\n0\n0\n3 " << triple(radiance)
                        << '\n'
                        << id << "_light sphere " << id << "\n0\n0\n4 " << triple(at) << ' '
                        << num(r) << "\n\n";
                    summary.materials += 1;  // the pattern's light below counts as well
                    break;
                }
            }
            ++summary.materials;
            ++summary.light_sources;
        }
        return true;
    }

    // A RADIANCE data file of the engine's own interpolation of the table, so both programs see
    // the same intensities: over γ ∈ [0°, 180°] and C ∈ [0°, 360°] (C varying fastest), or over γ
    // alone for a table alike in every C-plane. RADIANCE interpolates it linearly, which reads a
    // curve high where it bends: a narrow spot (cos⁴⁰ γ) sampled every degree read up to 1 % high
    // in its flank, so γ is sampled 4 times finer than C, and 20 times where it is all there is.
    // Returns the file's dimensions, 0 when it cannot be written.
    int write_intensity_data(const PreparedLuminaire& l, const fs::path& path) const {
        const double step = options.photometric_step_deg;
        const auto samples = [](double span, double every) {
            return static_cast<int>(std::lround(span / every)) + 1;
        };
        const auto angle = [](int k, int n, double span) { return span * kPi / 180 * k / (n - 1); };
        std::ofstream out(path);
        if (l.table->alike_all_round()) {
            const int ng = samples(180, step / 20);
            out << "1\n0 180 " << ng << '\n';
            for (int g = 0; g < ng; ++g) out << num(l.table->candela(angle(g, ng, 180), 0)) << '\n';
            return out ? 1 : 0;
        }
        const int ng = samples(180, step / 4), nc = samples(360, step);
        out << "2\n0 180 " << ng << "\n0 360 " << nc << '\n';
        for (int g = 0; g < ng; ++g) {
            for (int c = 0; c < nc; ++c) {
                out << num(l.table->candela(angle(g, ng, 180), angle(c, nc, 360)))
                    << (c + 1 == nc ? '\n' : ' ');
            }
        }
        return out ? 2 : 0;
    }

    bool write_points(const fs::path& path) {
        std::ofstream out(path);
        for (const PreparedSensorSet& set : scene.sensors) {
            summary.sensors.push_back({set.name, summary.points, set.points.size()});
            for (const Vec3& p : set.points) {
                out << triple(world(p)) << ' ' << triple(set.normal) << '\n';
            }
            summary.points += set.points.size();
        }
        return static_cast<bool>(out);
    }

    // About `surface_samples` points per surface: each convex piece as a fan of triangles, each
    // triangle cut into m² equal ones (m from its share of the surface's area), one point at
    // each centroid — the midpoint rule, exact for irradiance linear over a triangle.
    bool write_surface_samples(const fs::path& dir) {
        const int n = options.surface_samples;
        std::ofstream points(dir / "surface-points.txt"), samples(dir / "surface-samples.txt");
        samples << "# surface weight_m2 (one line per line of surface-points.txt)\n";
        const auto wanted = [&](const std::string& name) {
            const auto& only = options.sample_surfaces;
            return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
        };
        for (std::size_t s = 0; s < scene.surface_names.size(); ++s) {
            const std::string& name = scene.surface_names[s];
            const double area = scene.surface_area_m2[s];
            if (!wanted(name) || !(area > 0)) continue;
            SurfaceSamples out;
            out.name = name;
            out.surface = static_cast<int>(s);
            out.first = summary.surface_points;
            for (const Piece& p : scene.pieces) {
                if (p.surface != static_cast<int>(s)) continue;
                const PreparedMaterial& m = scene.materials[static_cast<std::size_t>(p.material)];
                out.reflectance = m.reflectance;
                out.exitance_lm_m2 = m.exitance_lm_m2;
                for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k) {
                    const Vec3 a = p.vertices[0];
                    const Vec3 e1 = p.vertices[k] - a, e2 = p.vertices[k + 1] - a;
                    const double t_area = 0.5 * length(cross(e1, e2));
                    const int m_div =
                        std::max(1, static_cast<int>(std::lround(std::sqrt(n * t_area / area))));
                    const double w = t_area / (m_div * m_div);
                    const auto emit = [&](double u, double v) {
                        points << triple(world(a + e1 * (u / m_div) + e2 * (v / m_div))) << ' '
                               << triple(p.normal) << '\n';
                        samples << name << ' ' << num(w) << '\n';
                        out.weights_m2.push_back(w);
                    };
                    for (int i = 0; i < m_div; ++i) {
                        for (int j = 0; i + j < m_div; ++j) {
                            emit(i + 1.0 / 3, j + 1.0 / 3);
                            if (i + j + 2 <= m_div) emit(i + 2.0 / 3, j + 2.0 / 3);
                        }
                    }
                }
            }
            summary.surface_points += out.weights_m2.size();
            summary.surfaces.push_back(std::move(out));
        }
        return points && samples;
    }

    std::string readme() const {
        std::ostringstream r;
        r << "RADIANCE version of the Radiant scene \"" << scene.name
          << "\", written by radiant-to-radiance.\n\n"
          << "Units: metres, Radiant's world frame. RADIANCE values are photometric / 179:\n"
          << "emitter radiance = exitance / (pi * 179), luminaire intensity = cd / 179.\n"
          << "Channels: " << summary.channels
          << (summary.channels == 1 ? " (gray scene: R = G = B)\n" : " (RGB, as Radiant's)\n")
          << "One-sided materials whose back is in view are black there (mixfunc on Rdot);\n"
          << "reflecting emitters are a light behind a thin plastic/void mixture (scene.rad).\n\n"
          << "Files: scene.rad (" << summary.polygons << " polygons, " << summary.light_sources
          << " light sources), points.txt (" << summary.points << " points: x y z nx ny nz):\n";
        for (const PointRange& s : summary.sensors) {
            r << "  lines " << s.first + 1 << "-" << s.first + s.count << ": sensor set \""
              << s.name << "\"\n";
        }
        if (options.surface_samples > 0) {
            r << "surface-points.txt (" << summary.surface_points
              << " points on surfaces) with surface-samples.txt (surface, area weight m2)\n";
        }
        r << "\nRADIANCE's lib (rayinit.cal; radiance-build/lib in a CMake build) must be on\n"
          << "RAYPATH; run in this directory:\n\n"
          << "  export RAYPATH=.:/path/to/radiance-build/lib\n"
          << "  oconv scene.rad > scene.oct\n"
          << "  rtrace -I -h -ab 8 -aa 0 -ad 2048 -lw 1e-4"
          << (summary.needs_all_shadow_tests ? " -dt 0" : "")
          << (summary.area_sources > 0 ? " -ds 0.02 -dj 1" : "")
          << " -n 2 scene.oct < points.txt > irradiance.txt\n"
          << "  rcalc -e '$1=179*(0.2126*$1+0.7152*$2+0.0722*$3)' irradiance.txt > lux.txt\n\n"
          << "lux.txt has one illuminance (lux) per point. The weights are Radiant's (Rec. 709),\n"
          << "not rtrace's own 0.265/0.670/0.065: Radiant's channels are RADIANCE's one for one.\n";
        if (summary.needs_all_shadow_tests) {
            r << "\nThis scene has emitters that also reflect: keep -dt 0 (every shadow ray "
                 "tested),\n"
              << "or rtrace adds the untested ones at 1/(1 - c) times their light.\n";
        }
        if (summary.area_sources > 0) {
            r << "\nThis scene has emitting surfaces: keep -dj 1. rtrace cuts a source into\n"
              << "parts (-ds) only for rays of high weight; the shadow rays of reflected light\n"
              << "aim at the source's centre unless jittered, so a wall near a large panel is\n"
              << "lit as if the panel were a point there (light seen close to a surface can be\n"
              << "2 % off). -ds 0.02 keeps the jitter's noise in the direct light small.\n";
        }
        return r.str();
    }
};

}  // namespace

ExportOutcome write_radiance_scene(const Scene& scene, const fs::path& dir,
                                   const ExportOptions& options) {
    ExportOutcome outcome;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        outcome.error = "cannot create " + dir.string() + ": " + ec.message();
        return outcome;
    }
    if (!(options.source_radius_m > 0) || !(options.photometric_step_deg > 0) ||
        options.photometric_step_deg > 90) {
        outcome.error = "the source radius must be positive and the photometric step in (0, 90]";
        return outcome;
    }
    const PreparedScene prepared = prepare_scene(scene);
    Writer w{prepared, options, {}, {}, {}, {}, false};
    w.summary.channels = prepared.channels;
    w.rad << "# radiant-to-radiance: the Radiant scene \"" << prepared.name
          << "\" in metres, world frame\n\n";
    w.write_materials();
    w.write_polygons();
    if (!w.write_luminaires(dir, outcome.error)) return outcome;
    {
        std::ofstream rad(dir / "scene.rad");
        rad << w.rad.str();
        if (!rad) {
            outcome.error = "cannot write " + (dir / "scene.rad").string();
            return outcome;
        }
    }
    if (!w.write_points(dir / "points.txt")) {
        outcome.error = "cannot write " + (dir / "points.txt").string();
        return outcome;
    }
    if (options.surface_samples > 0 && !w.write_surface_samples(dir)) {
        outcome.error = "cannot write the surface samples in " + dir.string();
        return outcome;
    }
    std::ofstream readme(dir / "README");
    readme << w.readme();
    if (!readme) {
        outcome.error = "cannot write " + (dir / "README").string();
        return outcome;
    }
    outcome.ok = true;
    outcome.summary = std::move(w.summary);
    return outcome;
}

std::vector<Rgb> irradiance_from_rtrace(std::istream& rtrace_output) {
    std::vector<Rgb> values;
    std::string line;
    while (std::getline(rtrace_output, line)) {
        std::istringstream in(line);
        Rgb e{};
        if (!(in >> e[0] >> e[1] >> e[2])) break;
        for (double& c : e) c *= kLumensPerWatt;
        values.push_back(e);
    }
    return values;
}

double photometric(const Rgb& c) { return luminance(c); }

SurfaceAverages surface_average(const SurfaceSamples& samples,
                                const std::vector<Rgb>& irradiance_lux) {
    Rgb e{0, 0, 0};
    double area = 0;
    for (std::size_t i = 0; i < samples.weights_m2.size(); ++i) {
        const std::size_t line = samples.first + i;
        if (line >= irradiance_lux.size()) return {std::nan(""), std::nan("")};
        for (int k = 0; k < 3; ++k) e[k] += samples.weights_m2[i] * irradiance_lux[line][k];
        area += samples.weights_m2[i];
    }
    if (!(area > 0)) return {std::nan(""), std::nan("")};
    Rgb b{};
    for (int k = 0; k < 3; ++k) {
        e[k] /= area;
        b[k] = samples.reflectance[k] * e[k] + samples.exitance_lm_m2[k];
    }
    return {luminance(e), luminance(b)};
}

}  // namespace radiant::radiance
