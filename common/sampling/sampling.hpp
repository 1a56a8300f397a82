#pragma once
/// Every sampler of the lecture, beside its pdf: pure functions of uniform numbers u in
/// [0,1)^2. They never take a generator, so tests can feed them fixed inputs.
///
///   sampling/plane.hpp       the square [-1,1]^2 and the unit disk (per unit area)
///   sampling/hemisphere.hpp  uniform and cosine-weighted directions (per steradian)
///   sampling/cosine_power.hpp  the family p ~ cos^m(theta), and a pdf that favours grazing
///                            directions (chapter 07)
///   sampling/phong.hpp       a glossy lobe round the mirror direction (normalised modified
///                            Phong), with its diffuse mix (chapter 08)
///   sampling/sphere.hpp      uniform directions on the whole sphere
///   sampling/cone.hpp        uniform directions in a cone (the solid angle of a sphere light)
///   sampling/frame.hpp       local directions (normal = +z) to world directions

#include "sampling/cone.hpp"
#include "sampling/cosine_power.hpp"
#include "sampling/frame.hpp"
#include "sampling/hemisphere.hpp"
#include "sampling/phong.hpp"
#include "sampling/plane.hpp"
#include "sampling/sphere.hpp"
