#include "shadowvol/triangulation.h"

namespace shadowvol {

const char* toString(Triangulation t) { return t == Triangulation::Fixed ? "fixed" : "perfect"; }

bool parseTriangulation(const std::string& text, Triangulation& t) {
  if (text == "fixed") t = Triangulation::Fixed;
  else if (text == "perfect") t = Triangulation::Perfect;
  else return false;
  return true;
}

}  // namespace shadowvol
