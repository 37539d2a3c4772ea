/**
 * @file hovCompositing.h
 * @brief Premultiplied RGBA and the one "over" operator of the module.
 *
 * Every path (CPU cell projection, OpenGL projection through its CPU-side
 * preparation, ray casting) composites with Over(); there is no second copy of
 * this formula anywhere in the module.
 *
 * Colours are premultiplied by opacity (Porter & Duff 1984): a segment with
 * opacity A and premultiplied colour C seen in front of a background B gives
 * C + (1 - A) B.
 *
 * Thread safety: stateless, re-entrant.
 */
#ifndef hovCompositing_h
#define hovCompositing_h

namespace hov
{
/// Premultiplied RGBA in double precision.
struct RGBA
{
  double R = 0.0;
  double G = 0.0;
  double B = 0.0;
  double A = 0.0;
};

/// Porter-Duff "over": @p front in front of @p back (both premultiplied).
inline RGBA Over(const RGBA& front, const RGBA& back)
{
  const double transmit = 1.0 - front.A;
  return RGBA{ front.R + transmit * back.R, front.G + transmit * back.G,
    front.B + transmit * back.B, front.A + transmit * back.A };
}

/// Front-to-back accumulation: what is already in @p accum lies in front of @p behind.
inline void CompositeBehind(RGBA& accum, const RGBA& behind)
{
  accum = Over(accum, behind);
}

/// Back-to-front accumulation: @p inFront is drawn over what @p accum holds.
inline void CompositeInFront(RGBA& accum, const RGBA& inFront)
{
  accum = Over(inFront, accum);
}
}

#endif
