#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <variant>

#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// A pbrt texture as candela can use it: a constant factor times, optionally, one of the scene's images, looked
// up through pbrt's uv mapping (u' = uscale u + udelta, v' = vscale v + vdelta).
struct PbrtTexture {
  Vec3 factor{1, 1, 1};
  int32_t image = kNoTexture;
  Vec2 uvScale{1, 1};
  Vec2 uvOffset{0, 0};
};

// The named textures of a scene (`Texture "name" "spectrum"|"float" "class" ...`): imagemap (PNG, JPEG, TGA, BMP,
// HDR, EXR, PFM; invert), constant, scale, mix (of images: as an image of the mix) and 2D checkerboards (as an
// image of one period) are honoured; 3D checkerboards become the mean of their two inputs, other classes a
// constant grey, each with a warning. A texture is made (its images decoded, its mix baked) only when a material,
// a light or a shape first asks for it: a scene may define many textures it never uses.
class PbrtTextures {
 public:
  explicit PbrtTextures(PbrtContext& context) : context_(context) {}

  void define(const std::string& name, const std::string& valueType, const std::string& className,
              const PbrtParameters& params);
  // A material or light parameter: a texture it names (made now, if not before), a colour or number it gives, or
  // `fallback`.
  PbrtTexture value(const PbrtParameters& params, const std::string& name, Vec3 fallback);
  // An image file as a scene texture (cached by file and encoding); kNoTexture after a warning when unreadable.
  int32_t loadImage(const std::string& path, bool srgb, const std::string& file, size_t line);
  // A one-channel float image of `map` applied to the first channel (as a linear value) of `image`: the form a
  // material needs where its parameter is not linear in pbrt's texture value (roughness). Cached by `key`. As a
  // mix image, it is charged now (a refusal names `where`, "file:line", and `element`) but made only by
  // bakeImages, after the image it reads: a roughness of a mix does not bake the mix before the scene is known
  // to fit.
  int32_t mappedImage(int32_t image, const std::string& key, const std::function<float(float)>& map,
                      const std::string& where, const std::string& element);
  // The mean colour of `texture`: its factor times the mean of its image's texels (linear), for a material
  // parameter that takes one colour. A mix not baked yet is not baked for it (meanOfMix).
  Vec3 meanColour(const PbrtTexture& texture);
  // A 64 x 64 image of one period of a 2D checkerboard of two colours (the first where pbrt's tex1 goes), shared
  // by every checkerboard of the same colours; kNoTexture (after a warning) beyond kMaxCheckerboardImages.
  int32_t checkerboardImage(Vec3 first, Vec3 second);
  // An image of (1 - amount) first + amount second over pbrt's unit (u, v) square, each input looked up (nearest
  // texel) through its own uv mapping, as fine as the finest input there (at most 4096 texels a side, and
  // within --max-texture-size). Identical mixes share one image. The image is charged to the load's budget now
  // (a refusal names `where`, "file:line", and the texture's `name`) but baked only by bakeImages, or when its
  // texels are needed first: a scene whose mixes would not fit is refused before the time of baking any of them.
  int32_t mixedImage(const PbrtTexture& first, const PbrtTexture& second, const PbrtTexture& amount,
                     const std::string& where, const std::string& name);
  // Bakes every mix and mapped image not baked yet; the loader calls it once the scene is read.
  void bakeImages() { bakeThrough(INT32_MAX); }

 private:
  // A Texture directive, kept until something uses it, with the definitions its texture parameters named then.
  struct Definition {
    std::string name, valueType, className;
    PbrtParameters params;
    std::map<std::string, std::shared_ptr<Definition>> inputs;  // by texture name; null for a name not defined
    std::optional<PbrtTexture> made;
  };
  // Makes `definition` and, first, every texture it depends on (without recursion: chains of textures may be long).
  const PbrtTexture& made(const std::shared_ptr<Definition>& definition);
  PbrtTexture make(const Definition& definition);
  // A parameter of a texture being made: a texture among its inputs, a colour or number, or `fallback`.
  PbrtTexture input(const Definition& definition, const std::string& name, Vec3 fallback);

  // Bakes the mix and mapped images charged so far up to scene texture `image`, in order: the images a bake
  // reads (a mix's inputs, a mapped image's source) come before it.
  void bakeThrough(int32_t image);
  struct Mix {
    PbrtTexture first, second, amount;
  };
  struct Mapping {
    int32_t source;
    std::function<float(float)> map;
  };
  // The linear colour of `t` at pbrt's (u, v): its factor, times its image's nearest texel through its uv mapping.
  Vec3 colourAt(const PbrtTexture& t, float u, float v) const;
  // The colour of `mix` at (u, v), from its inputs (which must be baked).
  Vec3 colourAt(const Mix& mix, float u, float v) const;
  void bake(Texture& out, const Mix& mix) const;
  void bake(Texture& out, const Mapping& mapping) const;
  // The mean of the mix that fills `out` once baked, from its inputs at the texel centres of a grid as fine as
  // its image, at most kMeanGrid texels a side: a material that takes one colour (hair, subsurface) does not bake
  // a mix before the scene is known to fit, and a mean needs no finer grid. Inputs that are mixes themselves are
  // baked first.
  Vec3 meanOfMix(const Texture& out, const Mix& mix);
  static constexpr uint32_t kMeanGrid = 512;
  // A float copy of an image with its colour channels (as linear values) turned into 1 - value, for `invert`.
  int32_t invertedImage(int32_t image);

  PbrtContext& context_;
  std::map<std::string, std::shared_ptr<Definition>> named_;
  std::map<std::pair<std::string, bool>, int32_t> images_;
  std::map<int32_t, int32_t> inverted_;
  static constexpr size_t kMaxCheckerboardImages = 1024;
  std::map<std::tuple<float, float, float, float, float, float>, int32_t> checkerboards_;
  std::map<std::pair<int32_t, std::string>, int32_t> mapped_;
  std::map<int32_t, std::variant<Mix, Mapping>> unbaked_;  // by the index of the image each fills
  std::map<std::array<float, 24>, int32_t> mixes_;
};

}  // namespace candela
