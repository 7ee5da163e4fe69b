#pragma once
// How big the object is, as the planner sees it: its thinnest width, its extents along its shape
// frame's axes, and the smooth stand-in a shape with edges is planned through when its own plan
// fails (grasp_planner.cpp): the ellipsoid of those extents. Private to the planning layer.
//
// Frames: S the object's contact shape frame (GraspRequest::X_OS places it in O).

#include "graspsim/contact/contact_shape.h"
#include "graspsim/simbody.h"

namespace graspsim::planning {

// How far a shape reaches along each axis of S (m): the centre of its extent and half of it. A
// box's half-lengths, an ellipsoid's semi-axes (both centred on S's origin), and for a convex mesh
// the same measured through its surface (support points far out along +-x, y, z), so that a mesh
// of a box has that box's. Zero for the other shapes, which the planner starts otherwise.
struct ObjectExtents {
    SimTK::Vec3 centre_S{0, 0, 0};
    SimTK::Vec3 halfExtents{0, 0, 0};
};
ObjectExtents findObjectExtents(const contact::ContactShape& shape);

// The object's thinnest width (m): the least distance between two parallel planes holding it,
// over a fixed set of directions, from signed distances to far points (findSurfacePoint).
double calcObjectWidth(const contact::ContactShape& shape);

// Whether the shape's surface has edges, where its normal jumps (a box, a convex mesh).
bool hasEdges(const contact::ContactShape& shape);

// A smooth shape with the object's extents: the ellipsoid whose semi-axes are its half-extents,
// at their centre (X_SE: the ellipsoid's frame E in S). For a box, the ellipsoid inscribed in it.
struct SmoothStandIn {
    contact::ContactShape shape;
    SimTK::Transform X_SE;
};
// @throws graspsim::Error for a shape without three positive half-extents (a sphere, a capsule,
//         a cylinder): a caller's mistake, checked by hasEdges first.
SmoothStandIn findSmoothStandIn(const contact::ContactShape& shape);

}  // namespace graspsim::planning
