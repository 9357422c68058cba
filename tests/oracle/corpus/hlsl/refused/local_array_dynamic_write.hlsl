// Refused by D3DCompile (X3500): a write into a local array at an index known only at run time;
// ps_3_0 has no indexable temporaries, so the element cannot be an l-value.
float4 table[4];

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 local[4];
    for (int i = 0; i < 4; i++) local[i] = table[i] * v;
    int k = (int)abs(v.w);
    local[k % 4] = 0;
    return local[0] + local[1] + local[2] + local[3];
}
