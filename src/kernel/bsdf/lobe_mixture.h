#pragma once
#include "core/math.h"
#include "kernel/bsdf/bsdf_sample.h"

namespace candela {

// Models made of several lobes are sampled as a mixture: one lobe is chosen with a probability that depends on
// wo only, it proposes wi, and the sample carries the sum of all lobes' values and the mixture density
// sum_i p_i pdf_i(wi). That is one-sample MIS with the balance heuristic: unbiased as long as every lobe that
// can be non-zero has p_i > 0, and pdf() reports the same mixture density to the light sampler's MIS.
template <int N>
struct LobeChoice {
  float p[N];

  // `estimates` are each lobe's expected contribution (any non-negative guess); a lobe that can contribute
  // gets at least kFloor of its share so that rare lobes still get sampled.
  CANDELA_FN static LobeChoice fromEstimates(const float (&estimates)[N]) {
    constexpr float kFloor = 0.05f;
    LobeChoice c;
    float total = 0.0f;
    for (int i = 0; i < N; ++i) total += estimates[i];
    for (int i = 0; i < N; ++i)
      c.p[i] = total > 0.0f ? fmaxf(estimates[i] / total, estimates[i] > 0.0f ? kFloor : 0.0f) : 1.0f / N;
    float sum = 0.0f;
    for (int i = 0; i < N; ++i) sum += c.p[i];
    for (int i = 0; i < N; ++i) c.p[i] /= sum;
    return c;
  }

  // Picks a lobe with u in [0, 1).
  CANDELA_FN int choose(float u) const {
    float cdf = 0.0f;
    for (int i = 0; i < N - 1; ++i) {
      cdf += p[i];
      if (u < cdf && p[i] > 0.0f) return i;
    }
    for (int i = N - 1; i > 0; --i)
      if (p[i] > 0.0f) return i;
    return 0;
  }
};

// Completes a mixture sample once a lobe chosen by `choice` proposed wi: value and density of the whole model.
template <class Model, int N>
CANDELA_FN BsdfSample mixtureSample(const Model& model, Vec3 wo, Vec3 wi, float eta, const LobeChoice<N>& choice) {
  BsdfSample s;
  s.wi = wi;
  BsdfEval e = model.evalPdf(wo, wi, choice);
  s.pdf = e.pdf;
  if (!(s.pdf > 0.0f)) return s;
  s.f = e.f;
  s.eta = wi.z < 0.0f ? eta : 1.0f;
  s.valid = true;
  return s;
}

}  // namespace candela
