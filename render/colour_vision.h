// How a colour looks to a reader with one of the three common colour-vision deficiencies
// (deuteranopia, protanopia: red-green; tritanopia: blue-yellow; Machado, Oliveira and Fernandes
// 2009, severity 1, applied to linear RGB) and how far apart two colours look (CIE76
// difference in CIELAB): the palette's pairs a reader must tell apart are checked with them.
#pragma once

#include "render/image.h"

namespace plantsim::render {

enum class ColourVision { kNormal, kDeuteranopia, kProtanopia, kTritanopia };

/// The colour as seen with `vision`.
Rgb simulate(Rgb colour, ColourVision vision);

/// The CIE76 colour difference (Delta E*ab) of two sRGB colours: about 2.3 is just noticeable; a
/// legend's entries want 20 and more.
double colour_difference(Rgb a, Rgb b);

}  // namespace plantsim::render
