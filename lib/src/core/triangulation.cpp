#include "shadowvol/triangulation.h"

namespace shadowvol {

const char* toString(Triangulation t) { return nameIn(kTriangulationNames, t); }

bool parseTriangulation(const std::string& text, Triangulation& t) { return parseIn(kTriangulationNames, text, t); }

}  // namespace shadowvol
