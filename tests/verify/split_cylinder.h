#pragma once
// Seed 000, Figure 5's situation as an OBJ: a 12-sided cylinder whose rim vertices keep one normal
// for the side (radial) and one for the caps (axial). Patches 4i and 4i + 1 are side triangles,
// 4i + 2 and 4i + 3 the bottom and top caps. With mesh.normals "split" the side patches bulge
// along the rim and the caps stay flat: cracks at the 24 rim edges and nowhere else.
#include <cmath>
#include <string>

namespace tessref::test {

inline std::string split_cylinder_obj() {
  constexpr int n = 12;
  std::string obj;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    const std::string c = std::to_string(std::cos(a)), s = std::to_string(std::sin(a));
    obj += "v " + c + " " + s + " -1\nv " + c + " " + s + " 1\nvn " + c + " " + s + " 0\n";
  }
  obj += "v 0 0 -1\nv 0 0 1\nvn 0 0 -1\nvn 0 0 1\n";
  const auto f = [&](int a, int na, int b, int nb, int c, int nc) {
    obj += "f " + std::to_string(a) + "//" + std::to_string(na) + " " + std::to_string(b) + "//" + std::to_string(nb) +
           " " + std::to_string(c) + "//" + std::to_string(nc) + "\n";
  };
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n, b0 = 2 * i + 1, t0 = 2 * i + 2, b1 = 2 * j + 1, t1 = 2 * j + 2;
    f(b0, i + 1, b1, j + 1, t1, j + 1);
    f(b0, i + 1, t1, j + 1, t0, i + 1);
    f(2 * n + 1, n + 1, b1, n + 1, b0, n + 1);
    f(2 * n + 2, n + 2, t0, n + 2, t1, n + 2);
  }
  return obj;
}

}  // namespace tessref::test
