// Conforming split of a triangular prism (VTK wedge order: 0,1,2 bottom, 3,4,5 top, 3 above
// 0) into three tetrahedra (Dompierre et al., "How to subdivide pyramids, prisms and
// hexahedra into tetrahedra", 1999): every quad face is cut along the diagonal through its
// smallest global point id, so two prisms sharing a quad always cut it the same way, for
// any numbering. The tetrahedra are positively oriented when the prism is.
#pragma once
#include <cstdint>

namespace vob {

// ids: the six global point ids in VTK wedge order. out: three tetrahedra.
void split_prism(const int32_t ids[6], int32_t out[3][4]);

}  // namespace vob
