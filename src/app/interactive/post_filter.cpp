#include "app/interactive/post_filter.h"

namespace candela {

Image postFiltered(const Image& accumulated, const Image& emission, const PostSettings& post) {
  if (!post.bilateral) return accumulated;
  if (emission.pixels.empty()) return bilateralFilter(accumulated, post.bilateralParams);
  return bilateralFilter(accumulated, emission, post.bilateralParams);
}

}  // namespace candela
