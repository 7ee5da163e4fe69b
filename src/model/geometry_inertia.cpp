#include "graspsim/model/geometry_inertia.h"

#include "graspsim/error.h"
#include "graspsim/model/triangle_mesh.h"

#include <algorithm>
#include <cmath>

namespace graspsim::model {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Central inertia of a capsule along z: a cylinder plus two hemispheres whose centres of mass
// sit 3r/8 beyond the cylinder's end faces; hemisphere central transverse moment 83/320 m r^2.
Inertia calcCapsuleInertia(double r, double L, double density) {
    const double mCyl = density * kPi * r * r * L;
    const double mHemi = density * 2.0 / 3.0 * kPi * r * r * r;
    const double offset = L / 2 + 3 * r / 8;
    Inertia I;
    I.zz = mCyl * r * r / 2 + 2 * (2.0 / 5.0) * mHemi * r * r;
    I.xx = mCyl * (r * r / 4 + L * L / 12) + 2 * (83.0 / 320.0 * mHemi * r * r + mHemi * offset * offset);
    I.yy = I.xx;
    return I;
}

// Central inertia in the geometry's own frame G.
Inertia calcInertiaInGeometryFrame(const Geometry& g, double density) {
    const double m = density * calcVolume(g);
    Inertia I;
    switch (g.type) {
        case Geometry::Type::Sphere:
            I.xx = I.yy = I.zz = 2.0 / 5.0 * m * g.radius * g.radius;
            break;
        case Geometry::Type::Box: {
            const double a = 2 * g.halfLengths[0], b = 2 * g.halfLengths[1], c = 2 * g.halfLengths[2];
            I.xx = m * (b * b + c * c) / 12;
            I.yy = m * (a * a + c * c) / 12;
            I.zz = m * (a * a + b * b) / 12;
            break;
        }
        case Geometry::Type::Cylinder:
            I.xx = I.yy = m * (3 * g.radius * g.radius + g.length * g.length) / 12;
            I.zz = m * g.radius * g.radius / 2;
            break;
        case Geometry::Type::Capsule:
            I = calcCapsuleInertia(g.radius, g.length, density);
            break;
        case Geometry::Type::Ellipsoid: {
            const double a = g.semiAxes[0], b = g.semiAxes[1], c = g.semiAxes[2];
            I.xx = m * (b * b + c * c) / 5;
            I.yy = m * (a * a + c * c) / 5;
            I.zz = m * (a * a + b * b) / 5;
            break;
        }
        case Geometry::Type::Mesh: {
            // Unit-density inertia scales linearly with density.
            const Inertia unit = calcMeshMassProperties(*g.mesh).inertia;
            I = Inertia{density * unit.xx, density * unit.yy, density * unit.zz,
                        density * unit.xy, density * unit.xz, density * unit.yz};
            break;
        }
    }
    return I;
}

}  // namespace

double calcVolume(const Geometry& g) {
    switch (g.type) {
        case Geometry::Type::Sphere:
            return 4.0 / 3.0 * kPi * g.radius * g.radius * g.radius;
        case Geometry::Type::Box:
            return 8 * g.halfLengths[0] * g.halfLengths[1] * g.halfLengths[2];
        case Geometry::Type::Cylinder:
            return kPi * g.radius * g.radius * g.length;
        case Geometry::Type::Capsule:
            return kPi * g.radius * g.radius * g.length + 4.0 / 3.0 * kPi * g.radius * g.radius * g.radius;
        case Geometry::Type::Ellipsoid:
            return 4.0 / 3.0 * kPi * g.semiAxes[0] * g.semiAxes[1] * g.semiAxes[2];
        case Geometry::Type::Mesh:
            if (g.mesh) return calcMeshMassProperties(*g.mesh).mass;
            break;
    }
    throw InputError("geometry '" + g.name + "' (mesh " + g.meshFile +
                     "): graspsim computes the volume of a mesh only once it has read the file");
}

std::array<double, 3> calcPrincipalMoments(const Inertia& I) {
    // Closed-form eigenvalues of a symmetric 3x3 matrix (Smith 1961): with q = trace/3 and
    // B = (A - q 1)/p, the eigenvalues are q + 2p cos(phi + 2 pi k/3), phi = acos(det(B)/2)/3.
    const double offDiagonal = I.xy * I.xy + I.xz * I.xz + I.yz * I.yz;
    std::array<double, 3> moments{I.xx, I.yy, I.zz};
    if (offDiagonal > 0) {
        const double q = (I.xx + I.yy + I.zz) / 3;
        const double a = I.xx - q, b = I.yy - q, c = I.zz - q;
        const double p = std::sqrt((a * a + b * b + c * c + 2 * offDiagonal) / 6);
        const double det = a * (b * c - I.yz * I.yz) - I.xy * (I.xy * c - I.yz * I.xz) + I.xz * (I.xy * I.yz - b * I.xz);
        const double r = std::clamp(det / (2 * p * p * p), -1.0, 1.0);
        const double phi = std::acos(r) / 3;
        moments[2] = q + 2 * p * std::cos(phi);
        moments[0] = q + 2 * p * std::cos(phi + 2 * kPi / 3);
        moments[1] = 3 * q - moments[0] - moments[2];
    }
    std::sort(moments.begin(), moments.end());
    return moments;
}

Inertia reexpressInertia(const Inertia& I_G, const Transform& X_BG) {
    const double G[3][3] = {{I_G.xx, I_G.xy, I_G.xz}, {I_G.xy, I_G.yy, I_G.yz}, {I_G.xz, I_G.yz, I_G.zz}};
    double B[3][3] = {};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l) B[i][j] += X_BG.R[3 * i + k] * G[k][l] * X_BG.R[3 * j + l];
    return Inertia{B[0][0], B[1][1], B[2][2], B[0][1], B[0][2], B[1][2]};
}

MassProperties calcSolidMassProperties(const Geometry& g, double density) {
    MassProperties mp;
    mp.mass = density * calcVolume(g);
    // Only a mesh's centroid may lie off its geometry frame's origin.
    mp.p_BCm = g.type == Geometry::Type::Mesh ? g.X_BG.shiftFrameStationToBase(calcMeshMassProperties(*g.mesh).p_BCm)
                                              : g.X_BG.p;
    mp.inertia = reexpressInertia(calcInertiaInGeometryFrame(g, density), g.X_BG);
    return mp;
}

MassProperties calcSolidMassProperties(const std::vector<Geometry>& geometry, double density) {
    MassProperties total;
    std::vector<MassProperties> parts;
    for (const Geometry& g : geometry) {
        parts.push_back(calcSolidMassProperties(g, density));
        total.mass += parts.back().mass;
        for (int k = 0; k < 3; ++k) total.p_BCm[k] += parts.back().mass * parts.back().p_BCm[k];
    }
    if (total.mass <= 0) return total;
    for (int k = 0; k < 3; ++k) total.p_BCm[k] /= total.mass;
    // Parallel-axis theorem moves each part's central inertia to the common centre of mass.
    for (const MassProperties& part : parts) {
        const double d[3] = {part.p_BCm[0] - total.p_BCm[0], part.p_BCm[1] - total.p_BCm[1],
                             part.p_BCm[2] - total.p_BCm[2]};
        const double m = part.mass;
        total.inertia.xx += part.inertia.xx + m * (d[1] * d[1] + d[2] * d[2]);
        total.inertia.yy += part.inertia.yy + m * (d[0] * d[0] + d[2] * d[2]);
        total.inertia.zz += part.inertia.zz + m * (d[0] * d[0] + d[1] * d[1]);
        total.inertia.xy += part.inertia.xy - m * d[0] * d[1];
        total.inertia.xz += part.inertia.xz - m * d[0] * d[2];
        total.inertia.yz += part.inertia.yz - m * d[1] * d[2];
    }
    return total;
}

}  // namespace graspsim::model
