vs_3_0
// mova over blendindices and their negation (draw 1 of --verify puts them at quarters: halves), two components at once
dcl_position v0
dcl_blendindices v1
dcl_position o0
dcl_texcoord o1
dcl_texcoord1 o2
mova a0.xy, v1.xy
mov o1, c[a0.x + 4]
mova a0.zw, -v1.xy
mov o2, c[a0.w + 8]
mov o0, v0
