// Renders the built-in Cornell box through an installed libcandela and prints the image's size and mean.
#include <cstdio>

#include <candela/candela.h>

int main() {
  try {
    candela::api::RenderOptions options;
    options.width = 16;
    options.height = 12;
    options.samplesPerPixel = 2;
    options.backend = "cpu";
    const candela::api::Image image = candela::api::render(candela::api::Scene::load("cornell-box"), options).image;
    double sum = 0.0;
    for (size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
    std::printf("candela %s: %ux%u, mean %.3f\n", candela::api::version(), image.width(), image.height(),
                sum / double(image.size()));
    return sum > 0.0 ? 0 : 1;
  } catch (const candela::api::Error& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
