// Refused by D3DCompile (X3535): msad4 is a shader model 5 intrinsic.
float4 main(float4 a : TEXCOORD0) : COLOR
{
    uint4 r = msad4(1, uint2(2, 3), uint4(0, 0, 0, 0));
    return r * a;
}
