// The four kinds of particle of the sub-particle-scale texture (section 3.2 of Gotoh et al. 2004):
//   Droplet      an isolated liquid MPS particle (category 3), a moving mist source falling through the gas;
//   Mist         a fine droplet shed by a droplet source, moving through the gas;
//   Bubble       an isolated gas MPS particle (category 6), a moving micro-bubble source rising through the liquid;
//   MicroBubble  a fine bubble shed by a bubble source, moving through the liquid.
// Eqs. (21)-(22): the carrying fluid is the gas for droplets and mist, the liquid for bubbles and micro-bubbles.
#pragma once

#include <cstdint>

namespace mistfall {

enum class TextureKind : std::uint8_t { Droplet = 0, Mist = 1, Bubble = 2, MicroBubble = 3 };
inline constexpr int kTextureKinds = 4;

inline bool isSource(TextureKind k) { return k == TextureKind::Droplet || k == TextureKind::Bubble; }
// True when the kind moves through the liquid (bubbles), false when it moves through the gas (droplets, mist).
inline bool carriedByLiquid(TextureKind k) { return k == TextureKind::Bubble || k == TextureKind::MicroBubble; }
// The fine kind a source sheds.
inline TextureKind shedKind(TextureKind source) {
  return source == TextureKind::Droplet ? TextureKind::Mist : TextureKind::MicroBubble;
}
inline const char* toString(TextureKind k) {
  switch (k) {
    case TextureKind::Droplet: return "droplet";
    case TextureKind::Mist: return "mist";
    case TextureKind::Bubble: return "bubble";
    default: return "micro_bubble";
  }
}

}  // namespace mistfall
