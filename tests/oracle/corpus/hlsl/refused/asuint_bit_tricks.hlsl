// Refused by D3DCompile (X3543): asuint/asfloat reinterpret bits, and ps_3_0 registers hold
// floats only; the bitwise & and >> that follow are refused too (X3535). Code ported back from
// shader model 4 hits this.
float4 main(float4 packed : TEXCOORD0) : COLOR
{
    uint bits = asuint(packed.x);
    float lo = (bits & 0xffff) / 65535.0;
    float hi = (bits >> 16) / 65535.0;
    return float4(lo, hi, packed.yz);
}
