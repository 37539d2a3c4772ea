#include "hovSpecialFunctions.h"

#include <cerf.h> // libcerf: erfcx(), dawson() for real arguments

namespace hov
{
double Erfcx(double x)
{
  return ::erfcx(x);
}

double Dawson(double x)
{
  return ::dawson(x);
}
}
