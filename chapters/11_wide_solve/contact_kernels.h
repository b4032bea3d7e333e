#pragma once
// The contact solve written once for any lane count (lanes.h): warm start, one Gauss-Seidel
// sweep with or without position feedback, and restitution, over a ManifoldBlock. The scalar
// solver runs it with N = 1, one contact after another in the wide solver's order; the wide
// solver with N = kWideLanes over the colours. A lane's arithmetic is the same in both and never
// reads the lanes beside it, so the two give the same bits. One file per
// idea, each including the one before:
//   body_pack.h       gather and scatter of a block's bodies (body_pack_avx2.h, _avx512.h)
//   block_fill.h      a block's fields from its contacts
//   block_prepare.h   the rows' effective masses and the normal block's inverse
//   friction_patch.h  friction at the manifold's centre, rolling resistance
//   block_solve.h     warm start and the block's sweep
//   collide.h         collisions before contacts, restitution

#include "11_wide_solve/collide.h"
