// vs_2_0 writing only oPos: every other output is left unwritten.
vs_2_0
dcl_position v0
mov oPos, v0
