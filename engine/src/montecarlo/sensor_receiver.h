// How a sensor point receives light, by its kind (z is up): how much of the light arriving from a
// direction it counts, and the receiver planes its final gather samples. Every kind is an
// average of planar illuminances over a family of receiver normals — a vertical cylinder's sides
// are all horizontal normals, a half cylinder's the half that faces its way — so a gather that
// draws one normal of the family per ray (and per set for the emitting surfaces' exact factors)
// and casts cosine rays about it measures the kind with the planar estimator unchanged:
// averaging max(0, cos) over the family gives the kind's weight below.
#pragma once

#include "radiant/scene.h"
#include "radiant/vec3.h"

namespace radiant {

class SensorReceiver {
public:
    /// `normal`: unit; for the vertical kinds the horizontal facing (prepare_scene makes it so).
    SensorReceiver(SensorKind kind, const Vec3& normal) : kind_(kind), normal_(normal) {}

    SensorKind kind() const { return kind_; }
    /// Whether every ray uses the one normal (planar and vertical sensors).
    bool fixed() const { return kind_ == SensorKind::planar || kind_ == SensorKind::vertical; }

    /// The share of the light arriving from unit direction `to_source` that the sensor counts:
    /// planar max(0, n·ω); cylindrical |ω_h|/π; semi-cylindrical (|ω_h| + n·ω_h)/π, with ω_h the
    /// horizontal part of ω. A point source of intensity I at distance d gives I·weight/d².
    double weight(const Vec3& to_source) const;

    /// The receiver normal at `u` ∈ [0, 1) across the kind's family: uniform u gives each normal
    /// its share of the average.
    Vec3 normal_at(double u) const;

    /// Where shadow rays start from, off the point: along the normal (a sensor may lie on a
    /// desk), straight up for a cylinder.
    Vec3 offset_normal() const {
        return kind_ == SensorKind::cylindrical ? Vec3{0, 0, 1} : normal_;
    }

private:
    SensorKind kind_;
    Vec3 normal_;
};

}  // namespace radiant
