#include "reference_cache.h"

#include <cstdio>
#include <fstream>
#include <system_error>
#include <variant>

#include <nlohmann/json.hpp>

namespace radiant::bench {
namespace {

namespace fs = std::filesystem;

class Fnv1a {
public:
    void add(const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
        }
    }
    void add(double v) { add(&v, sizeof v); }
    void add(const Vec3& v) {
        add(v.x);
        add(v.y);
        add(v.z);
    }
    void add(const std::string& s) { add(s.data(), s.size() + 1); }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace

std::uint64_t scene_fingerprint(const Scene& scene) {
    Fnv1a h;
    h.add(meters_per_unit(scene.units));
    for (const auto& m : scene.materials) {
        h.add(m.name);
        for (const double r : m.reflectance) h.add(r);
        h.add(m.emission ? m.emission->value : -1.0);
        h.add(m.emission && m.emission->kind == Emission::Kind::flux ? 1.0 : 0.0);
        h.add(m.two_sided ? 1.0 : 0.0);
    }
    for (const auto& s : scene.surfaces) {
        h.add(s.name);
        h.add(s.material);
        if (const auto* poly = std::get_if<Polygon>(&s.geometry)) {
            for (const auto& p : *poly) h.add(p);
        } else if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
            for (const auto& p : mesh->vertices) h.add(p);
            for (const auto& f : mesh->faces) h.add(f.data(), f.size() * sizeof(int));
        } else {
            const auto& box = std::get<BoxGeometry>(s.geometry);
            h.add(box.min);
            h.add(box.max);
            h.add(box.facing_in ? 1.0 : 0.0);
        }
    }
    for (const auto& l : scene.luminaires) {
        h.add(l.position);
        h.add(l.aim);
        h.add(l.flux_lm.value_or(-1.0));
        h.add(static_cast<double>(l.distribution));
        h.add(l.rotation_deg);
        if (l.photometry) {
            for (const auto* values :
                 {&l.photometry->gamma_deg, &l.photometry->c_deg, &l.photometry->candela}) {
                for (const double v : *values) h.add(v);
            }
        }
    }
    for (const auto& set : scene.sensors) {
        h.add(set.name);
        h.add(set.normal);
        for (const auto& p : set.points) h.add(p);
    }
    return h.value();
}

fs::path ReferenceCache::file_for(const Scene& scene, double tolerance) const {
    char name[128];
    std::snprintf(name, sizeof name, "-%016llx-tol%g.json",
                  static_cast<unsigned long long>(scene_fingerprint(scene)), tolerance);
    return directory_ / (scene.name + name);
}

std::optional<CachedReference> ReferenceCache::find(const Scene& scene, double tolerance) const {
    const fs::path file = file_for(scene, tolerance);
    std::error_code ec;
    const auto cached = fs::last_write_time(file, ec);
    if (ec) return std::nullopt;
    const auto engine = fs::last_write_time(RADIANT_ENGINE_LIBRARY, ec);
    if (ec || cached < engine) return std::nullopt;  // made by an older engine
    std::ifstream in(file);
    const auto doc = nlohmann::json::parse(in, nullptr, false);
    // Entries that kept maintained values (before "new_lamp_illuminance") are made again.
    if (doc.is_discarded() || !doc.contains("new_lamp_illuminance")) return std::nullopt;
    return CachedReference{doc.at("new_lamp_illuminance").get<std::vector<double>>(),
                           doc.at("seconds").get<double>(), doc.at("error_estimate").get<double>()};
}

void ReferenceCache::store(const Scene& scene, double tolerance,
                           const CachedReference& reference) const {
    std::error_code ec;
    fs::create_directories(directory_, ec);
    const fs::path file = file_for(scene, tolerance);
    const fs::path partial = file.string() + ".partial";
    {
        std::ofstream out(partial);
        out << nlohmann::json{{"new_lamp_illuminance", reference.illuminance},
                              {"seconds", reference.seconds},
                              {"error_estimate", reference.error_estimate}}
                   .dump();
    }
    fs::rename(partial, file, ec);  // whole entries only, even if the run is interrupted
}

}  // namespace radiant::bench
