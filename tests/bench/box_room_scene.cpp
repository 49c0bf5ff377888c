#include "box_room_scene.h"

#include <array>
#include <sstream>
#include <string>

namespace radiant::bench {
namespace {

using Json = nlohmann::ordered_json;

// Counter-clockwise in the face's (u, v) turns its front to u × v: +z for floor and ceiling,
// −y for the south and north walls, +x for west and east. Every face looks into the room, so
// floor, north and west are counter-clockwise and the others clockwise.
bool counter_clockwise(int face) {
    return face == floor_face || face == north_face || face == west_face;
}

Json point(const BoxRoom& room, int face, double u, double v) {
    const BoxFaceFrame frame = box_face_frame(face);
    std::array<double, 3> p{};
    p[frame.normal] = frame.far ? room.size[frame.normal] : 0.0;
    p[frame.u] = u;
    p[frame.v] = v;
    return Json::array({p[0], p[1], p[2]});
}

/// Corner indices (i, j) of a cell, in the order that faces into the room.
std::array<std::array<int, 2>, 4> corners(int face, int i, int j) {
    if (counter_clockwise(face)) return {{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
    return {{{i, j}, {i, j + 1}, {i + 1, j + 1}, {i + 1, j}}};
}

Json rectangle(const BoxRoom& room, int face, double u0, double u1, double v0, double v1) {
    const double us[] = {u0, u1}, vs[] = {v0, v1};
    Json polygon = Json::array();
    for (const auto& [i, j] : corners(face, 0, 0))
        polygon.push_back(point(room, face, us[i], vs[j]));
    return polygon;
}

/// The face around the panel: a 3 × 3 grid of rectangles without its centre.
Json ring_mesh(const BoxRoom& room, int face, const BoxPanel& panel) {
    const BoxFaceFrame frame = box_face_frame(face);
    const double us[] = {0, panel.u0, panel.u1, room.size[frame.u]};
    const double vs[] = {0, panel.v0, panel.v1, room.size[frame.v]};
    Json vertices = Json::array(), faces = Json::array();
    for (double u : us) {
        for (double v : vs) vertices.push_back(point(room, face, u, v));
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (i == 1 && j == 1) continue;
            Json f = Json::array();
            for (const auto& [ci, cj] : corners(face, i, j)) f.push_back(ci * 4 + cj);
            faces.push_back(f);
        }
    }
    return {{"vertices", vertices}, {"faces", faces}};
}

Json material(const FaceMaterial& m) {
    Json j{{"reflectance", m.reflectance}};
    if (m.exitance > 0) j["emission"] = {{"exitance", m.exitance}};
    return j;
}

Json check(const std::string& surface, const char* field, const ExtrapolatedMean& mean,
           double rel_tol, const std::string& why) {
    return {{"what", "surface"},   {"surface", surface}, {"field", field},
            {"value", mean.value}, {"rel_tol", rel_tol}, {"why", why}};
}

}  // namespace

nlohmann::ordered_json box_room_scene(const BoxRoom& room) {
    Json materials = Json::object(), surfaces = Json::array();
    for (int f = 0; f < kBoxFaces; ++f) {
        const std::string name = box_face_name(f);
        materials[name] = material(room.faces[f]);
        Json surface{{"name", name}, {"material", name}};
        const BoxFaceFrame frame = box_face_frame(f);
        if (room.panel && room.panel->face == f) {
            surface["mesh"] = ring_mesh(room, f, *room.panel);
        } else {
            surface["polygon"] = rectangle(room, f, 0, room.size[frame.u], 0, room.size[frame.v]);
        }
        surfaces.push_back(surface);
    }
    if (room.panel) {
        const BoxPanel& p = *room.panel;
        materials["panel"] = material(p.material);
        surfaces.push_back({{"name", "panel"},
                            {"material", "panel"},
                            {"polygon", rectangle(room, p.face, p.u0, p.u1, p.v0, p.v1)}});
    }
    Json scene{{"format", "radiant-scene/1"},
               {"name", room.name},
               {"units", "m"},
               {"materials", materials},
               {"surfaces", surfaces}};
    if (!room.luminaires.empty()) {
        Json luminaires = Json::array();
        for (std::size_t i = 0; i < room.luminaires.size(); ++i) {
            const auto& l = room.luminaires[i];
            std::string name = "L";  // not "L" + to_string: GCC 12's -Wrestrict false positive
            name += std::to_string(i + 1);
            luminaires.push_back({{"name", name},
                                  {"position", {l.position[0], l.position[1], l.position[2]}},
                                  {"flux", l.flux_lm},
                                  {"distribution", "isotropic"}});
        }
        scene["luminaires"] = luminaires;
    }
    scene["settings"] = {{"tolerance", 0.01}};
    return scene;
}

nlohmann::ordered_json box_room_checks(const BoxRoom& room, const BoxRoomReference& reference,
                                       double rel_tol) {
    const auto why = [&](const ExtrapolatedMean& m) {
        std::ostringstream s;
        s << "converged continuous solution: dense Galerkin with exact patch form factors at "
          << reference.resolutions[0] << "/" << reference.resolutions[1] << "/"
          << reference.resolutions[2] << " cells per metre, Richardson-extrapolated (uncertainty "
          << m.uncertainty << ")";
        return s.str();
    };
    Json checks = Json::array();
    for (int f = 0; f < kBoxFaces; ++f) {
        checks.push_back(check(box_face_name(f), "average_radiosity", reference.radiosity[f],
                               rel_tol, why(reference.radiosity[f])));
        checks.push_back(check(box_face_name(f), "average_irradiance", reference.irradiance[f],
                               rel_tol, why(reference.irradiance[f])));
    }
    if (room.panel) {
        checks.push_back(check("panel", "average_radiosity", reference.panel_radiosity, rel_tol,
                               why(reference.panel_radiosity)));
        checks.push_back(check("panel", "average_irradiance", reference.panel_irradiance, rel_tol,
                               why(reference.panel_irradiance)));
    }
    checks.push_back({{"what", "energy"},
                      {"rel_tol", 0.001},
                      {"why", "closed scene: absorbed flux equals emitted flux"}});
    return checks;
}

}  // namespace radiant::bench
