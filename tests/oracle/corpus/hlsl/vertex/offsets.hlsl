// oracle: target=vs_3_0
// A loop over a uniform count adding offsets from a constant array (c[aL] reads), and the
// sign of the position into TEXCOORD1.
int count : register(i0);
float4 offsets[6] : register(c0);

struct VOut {
    float4 pos : POSITION;
    float4 sgn : TEXCOORD1;
};

VOut main(float4 p : POSITION) {
    VOut o;
    float4 r = p;
    for (int i = 0; i < count; i++) {
        r += offsets[i];
    }
    o.pos = r;
    o.sgn = sign(p);
    return o;
}
