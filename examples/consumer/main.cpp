// SPDX-License-Identifier: LGPL-3.0-or-later
// Builds the exact BSP of two crossing triangles through the installed exbsp package and
// prints the back-to-front order for an eye above them, with exact coordinates as GMP
// rationals (exbsp/bsp/exact_gmp.h). Exit status 0 when all is as expected.
#include <exbsp/bsp/engine.h>
#include <exbsp/bsp/exact_gmp.h>
#include <exbsp/core/version.h>

#include <cstdio>

int main() {
  exbsp::triangle_soup soup;
  soup.add_triangle({0, 0, 0}, {4, 0, 0}, {0, 4, 0});   // face 0: the plane z = 0
  soup.add_triangle({1, 1, -1}, {2, 1, 1}, {1, 2, 1});  // face 1: crosses it
  exbsp::build_options options;
  options.heuristic = "naive";
  const exbsp::bsp tree = exbsp::bsp::build(soup, options);
  std::printf("%zu fragments, %zu splits, kernel %s\n", tree.stats().fragments, tree.stats().splits,
              tree.stats().kernel.c_str());
  bool exact_agrees = true;
  for (std::uint32_t i : tree.order_from_eye({1, 1, 10})) {
    const exbsp::exact_triangle e = tree.fragment_exact(i);
    const exbsp::exact_triangle_mpq q = exbsp::fragment_exact_mpq(tree, i);
    std::printf("face %u: (%s, %s, %s) ...\n", tree.fragment(i).face, e[0][0].c_str(),
                e[0][1].c_str(), e[0][2].c_str());
    for (int v = 0; v < 3; ++v)
      for (int a = 0; a < 3; ++a) exact_agrees = exact_agrees && q[v][a] == mpq_class(e[v][a]);
  }
  std::printf("exbsp %s\n", exbsp::version_string);
  return tree.stats().splits == 1 && tree.stats().fragments == 4 && exact_agrees ? 0 : 1;
}
