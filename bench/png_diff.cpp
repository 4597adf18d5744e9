// The largest difference between two PNGs of the same size, per channel in 1/255 (both read as RGBA by
// stb_image). Usage: png_diff A.png B.png. Prints "max M differing N": N channel values differ, the largest
// by M levels. Exit status 2 when a file is unreadable or the sizes differ. scripts/compare-renders uses it.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: png_diff A.png B.png\n");
    return 2;
  }
  int w[2], h[2], channels;
  unsigned char* px[2];
  for (int k = 0; k < 2; ++k)
    if (!(px[k] = stbi_load(argv[1 + k], &w[k], &h[k], &channels, 4))) {
      std::fprintf(stderr, "png_diff: cannot read %s\n", argv[1 + k]);
      return 2;
    }
  if (w[0] != w[1] || h[0] != h[1]) {
    std::fprintf(stderr, "png_diff: %dx%d against %dx%d\n", w[0], h[0], w[1], h[1]);
    return 2;
  }
  int most = 0;
  long differing = 0;
  for (long i = 0; i < 4L * w[0] * h[0]; ++i) {
    const int d = std::abs(px[0][i] - px[1][i]);
    most = d > most ? d : most;
    differing += d > 0;
  }
  std::printf("max %d differing %ld\n", most, differing);
  stbi_image_free(px[0]), stbi_image_free(px[1]);
}
