// Builds the exact BSP of two crossing triangles through the installed exbsp package and
// prints the back-to-front order for an eye above them. Exit status 0 when all is as expected.
#include <exbsp/bsp/engine.h>

#include <cstdio>

int main() {
  exbsp::triangle_soup soup;
  soup.add_triangle({0, 0, 0}, {4, 0, 0}, {0, 4, 0});   // face 0: the plane z = 0
  soup.add_triangle({1, 1, -1}, {2, 1, 1}, {1, 2, 1});  // face 1: crosses it
  exbsp::build_options options;
  options.heuristic = "naive";
  const exbsp::bsp tree = exbsp::bsp::build(soup, options);
  std::printf("%zu fragments, %zu splits, kernel %s\n", tree.stats().fragments,
              tree.stats().splits, tree.stats().kernel.c_str());
  for (std::uint32_t i : tree.order_from_eye({1, 1, 10})) {
    const exbsp::exact_triangle e = tree.fragment_exact(i);
    std::printf("face %u: (%s, %s, %s) ...\n", tree.fragment(i).face, e[0][0].c_str(),
                e[0][1].c_str(), e[0][2].c_str());
  }
  return tree.stats().splits == 1 && tree.stats().fragments == 4 ? 0 : 1;
}
