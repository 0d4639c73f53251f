#pragma once
// Where PRM's sampling phase draws its configurations: uniformly (the homework's PRM), near the
// obstacles' boundaries (Gaussian), inside narrow passages (the bridge test), or from a
// low-dispersion sequence (Halton). The lesson a student needs after PRM is why uniform sampling
// starves a narrow passage and what these do about it.
//
// One draw of a sampler is one of PRM's n samples ("samples" counts draws, i.e. attempts, not the
// configurations kept); a draw keeps at most one configuration:
// - uniform: q uniform in Q; kept if free (one configuration tested).
// - gaussian:S (Boor, Overmars, van der Stappen 1999): q1 uniform, q2 = q1 + S * z with z a
//   standard normal vector in the space's metric (coordinate i moves by S z_i / w_i); kept: the one
//   of q1, q2 that is free if exactly one is (two tested).
// - bridge:S (Hsu et al. 2003): q1 uniform; q1 free: nothing kept (one tested); else q2 as for
//   gaussian; q2 free: nothing kept (two tested); else the midpoint of q1 and q2 (the shorter way
//   round on S^1), kept if free (three tested).
// - gaussian:S,uniform:W and bridge:S,uniform:W, W in (0, 1) (the hybrids of Hsu et al. 2003):
//   with chance W a draw is a uniform one, otherwise the sampler's own. A bridge alone keeps points
//   in passages only, which start and goal out in the open rarely see; the uniform share covers
//   the open space. (One more random number per draw, taken only when W > 0: the plain samplers
//   keep their bits.)
// - halton: the i-th point of the Halton sequence (bases 2, 3, 5, ... per coordinate, i = 1, 2,
//   ... the draw's number) scaled to the bounds (S^1 over [-pi, pi)); kept if free. It takes no
//   random number: the seed plays no part in it.
// q2 is clamped into the bounds of linear coordinates and wrapped on S^1, as OMPL's samplers do
// (a robot cannot leave the workspace's box). Normal deviates come from the lab's Rng by
// Marsaglia's polar method with det::log: the same bits natively and in wasm.
#include <cstdint>
#include <string>
#include <vector>

#include "core/base/config.hpp"
#include "core/base/rng.hpp"
#include "core/checking/collision.hpp"
#include "core/spaces/space.hpp"

namespace csl {

struct SamplerSpec {
  enum class Kind { Uniform, Gaussian, Bridge, Halton } kind = Kind::Uniform;
  double sigma = 0.0;  ///< gaussian and bridge: the standard deviation, in the space's metric
  double uniform_share = 0.0;  ///< gaussian and bridge: the chance that a draw is a uniform one
  /// "uniform", "gaussian:S", "bridge:S" or "halton" (S a finite number > 0), gaussian and bridge
  /// optionally followed by ",uniform:W" (W in [0, 1)); throws std::invalid_argument with a
  /// one-line reason.
  static SamplerSpec parse(const std::string& text);
  /// The text parse() reads back to the same spec ("gaussian:0.05", "bridge:0.05,uniform:0.3").
  std::string name() const;
};

/// What one draw gave. Kept: `q` is the new vertex. Not kept: `q` is the configuration that
/// decided it, `q_free` whether it is free (a free q rejected: the Gaussian pair both free, or a
/// bridge's end free; otherwise q is in collision and the event names its obstacle).
struct SamplerDraw {
  Config q;
  bool kept = false;
  bool q_free = false;
  int tested = 0;  ///< configurations the draw tested for collision
};

class Sampler {
 public:
  Sampler(const CollisionWorld& world, SamplerSpec spec);
  const SamplerSpec& spec() const { return spec_; }
  /// Draw number `index` (1, 2, ...: Halton's index) with the planner's rng.
  SamplerDraw draw(Rng& rng, int index) const;

 private:
  Config gaussian_partner(Rng& rng, const Config& q1) const;
  const CollisionWorld* world_;
  SamplerSpec spec_;
  std::vector<int> bases_;  // Halton: the first dim() primes
};

/// `count` standard normal deviates (Marsaglia's polar method; pairs, an odd count drops the
/// last one's twin): how the Gaussian and bridge samplers perturb a configuration.
void normal_deviates(Rng& rng, int count, double* out);
/// The radical inverse of i in `base`: Halton's coordinate, in [0, 1).
double radical_inverse(std::uint64_t i, int base);
/// The i-th point (i >= 1) of the Halton sequence scaled to `space`'s bounds.
Config halton_point(const Space& space, std::uint64_t i);

}  // namespace csl
