// vs_2_0 writing oPos, and only x of oD0 and oT0 (Wine's vs2_partial_code).
vs_2_0
dcl_position v0
def c0, 0.5, 0.5, 0.5, 0.5
mov oPos, v0
mov oD0.x, c0
mov oT0.x, c0
