// The measurement behind docs/contact.md, "Why our own geometry and not FCL/libccd": FCL 0.7's
// penetration depth (libccd GJK/EPA, and FCL's own GJK/EPA) against the exact depth, for a
// fingertip sphere (8 mm) on an ellipsoid and on a cylinder's side, and a palm box face on an
// ellipsoid's pole, with the exact depth swept from 0.5 to 2.5 mm in 1 um steps. Not part of the
// build (graspsim does not use FCL). Run:
//   apt-get install libfcl-dev
//   g++ -O2 -std=c++17 -I/usr/include/eigen3 analysis/fcl_depth_comparison.cpp -lfcl -lccd -o /tmp/fcl_depth_comparison
//   /tmp/fcl_depth_comparison
#include <fcl/fcl.h>
#include <cmath>
#include <cstdio>
#include <memory>
using namespace fcl;

double depthOf(std::shared_ptr<CollisionGeometryd> a, const Transform3d& ta,
               std::shared_ptr<CollisionGeometryd> b, const Transform3d& tb, GJKSolverType solver) {
  CollisionObjectd oa(a, ta), ob(b, tb);
  CollisionRequestd req(1, true);
  req.gjk_solver_type = solver;
  CollisionResultd res;
  collide(&oa, &ob, req, res);
  if (!res.isCollision()) return 0;
  return res.getContact(0).penetration_depth;
}

void sweep(const char* name, std::shared_ptr<CollisionGeometryd> obj, std::shared_ptr<CollisionGeometryd> probe,
           Vector3d P, Vector3d n, double offset, GJKSolverType solver) {
  double maxErr = 0, maxJump = 0, prevErr = 0;
  for (int i = 0; i <= 2000; ++i) {
    const double delta = 0.0005 + 1e-6 * i;  // 0.5 .. 2.5 mm
    Transform3d tb = Transform3d::Identity();
    tb.translation() = P + (offset - delta) * n;
    const double d = depthOf(obj, Transform3d::Identity(), probe, tb, solver);
    const double err = d - delta;
    maxErr = std::max(maxErr, std::abs(err));
    if (i > 0) maxJump = std::max(maxJump, std::abs(err - prevErr));
    prevErr = err;
  }
  std::printf("%-34s %-7s max |depth error| %.3g m, max error change per 1 um step %.3g m\n", name,
              solver == GST_LIBCCD ? "libccd" : "indep", maxErr, maxJump);
}

int main() {
  const double a = 0.04, b = 0.03, c = 0.02, r = 0.008;
  auto ell = std::make_shared<Ellipsoidd>(a, b, c);
  auto cyl = std::make_shared<Cylinderd>(0.03, 0.1);
  auto tip = std::make_shared<Sphered>(r);
  auto palm = std::make_shared<Boxd>(0.08, 0.1, 0.02);
  // A general ellipsoid surface point and its normal.
  const double u = 0.7, v = -0.4;
  Vector3d P(a * std::cos(v) * std::cos(u), b * std::cos(v) * std::sin(u), c * std::sin(v));
  Vector3d n(P[0] / (a * a), P[1] / (b * b), P[2] / (c * c));
  n.normalize();
  for (GJKSolverType s : {GST_LIBCCD, GST_INDEP}) {
    sweep("fingertip on ellipsoid", ell, tip, P, n, r, s);
    sweep("fingertip on cylinder side", cyl, tip, Vector3d(0.03 / std::sqrt(2), 0.03 / std::sqrt(2), 0.01),
          Vector3d(1 / std::sqrt(2), 1 / std::sqrt(2), 0), r, s);
    sweep("palm box face on ellipsoid pole", ell, palm, Vector3d(0, 0, c), Vector3d(0, 0, 1), 0.01, s);
  }
}
