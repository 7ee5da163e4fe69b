#pragma once
// Grasps whose quality is known in closed form, shared by the grasp tests.
//
// The lemma every hand computation below uses: for a contact with unit normal n and unit normal
// force, the sum over its basis forces of f f^T is
//     box cone:              4 n n^T + 4 mu^2 (I - n n^T)        (cross terms cancel in pairs)
//     polyhedral, k edges:   k n n^T + (k mu^2 / 2)(I - n n^T)
//                            (k >= 3: sum cos = sum sin cos = 0, sum cos^2 = k/2)
// so, writing M_i for it and c_i for p_OC_i, G G^T = sum_i [I ; c_i^] M_i [I , c_i^T^]
//     = sum_i [ M_i , M_i c_i^T^ ; c_i^ M_i , c_i^ M_i c_i^T^ ].
// M_i does not depend on the tangent basis, hence neither do G G^T nor sigma_min.

#include "graspsim/grasp/grasp_contact.h"

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace graspsim::grasp::examples {

const double kPi = 3.14159265358979323846;

// Two fingers pushing on opposite sides of a sphere of radius r centred at O = G:
// contacts at (+-r, 0, 0), normals (-+1, 0, 0).
inline std::vector<GraspContact> antipodalGrasp(double r) {
    GraspContact a, b;
    a.p_GC = {r, 0, 0};
    a.n_G = {-1, 0, 0};
    b.p_GC = {-r, 0, 0};
    b.n_G = {1, 0, 0};
    return {a, b};
}

// Three fingers 120 degrees apart on the equator (z = 0) of a sphere of radius r at O = G.
inline std::vector<GraspContact> threeFingerGrasp(double r) {
    std::vector<GraspContact> contacts;
    for (int i = 0; i < 3; ++i) {
        const double th = 2 * kPi * i / 3;
        GraspContact c;
        c.p_GC = r * Eigen::Vector3d(std::cos(th), std::sin(th), 0);
        c.n_G = -c.p_GC / r;
        contacts.push_back(c);
    }
    return contacts;
}

// One finger at the centre of each face of a cube of half-size a at O = G, pushing inward, with
// friction tangents along the cube's edges.
inline std::vector<GraspContact> cubeGrasp(double a) {
    std::vector<GraspContact> contacts;
    for (int axis = 0; axis < 3; ++axis) {
        for (double side : {1.0, -1.0}) {
            GraspContact c;
            c.p_GC = side * a * Eigen::Vector3d::Unit(axis);
            c.n_G = -side * Eigen::Vector3d::Unit(axis);
            c.t_G = Eigen::Vector3d::Unit((axis + 1) % 3);
            contacts.push_back(c);
        }
    }
    return contacts;
}

// Three fingers under an object, all pushing up (+y) with small tilts: every force, hence every
// wrench, has a positive y component, so the grasp cannot resist a push upward.
inline std::vector<GraspContact> supportGrasp() {
    std::vector<GraspContact> contacts;
    const Eigen::Vector3d points[3] = {
        {0.03, -0.02, 0.0}, {-0.02, -0.02, 0.03}, {-0.01, -0.02, -0.03}};
    const Eigen::Vector3d normals[3] = {{0.2, 1, 0}, {-0.1, 1, 0.2}, {0, 1, -0.2}};
    for (int i = 0; i < 3; ++i) {
        GraspContact c;
        c.p_GC = points[i];
        c.n_G = normals[i].normalized();
        contacts.push_back(c);
    }
    return contacts;
}

// The same grasp seen from another world frame: every ground-frame quantity (contacts and object
// frame) moved by the rigid motion x -> R x + p.
inline void moveRigidly(std::vector<GraspContact>& contacts, ObjectFrame& frame,
                        const Eigen::Matrix3d& R, const Eigen::Vector3d& p) {
    for (GraspContact& c : contacts) {
        c.p_GC = R * c.p_GC + p;
        c.n_G = R * c.n_G;
        c.t_G = R * c.t_G;
    }
    frame.R_GO = R * frame.R_GO;
    frame.p_GO = R * frame.p_GO + p;
}

inline Eigen::Matrix3d someRotation() {
    return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
            Eigen::AngleAxisd(-1.9, Eigen::Vector3d(-2, 0.5, 1).normalized()))
        .toRotationMatrix();
}

}  // namespace graspsim::grasp::examples
