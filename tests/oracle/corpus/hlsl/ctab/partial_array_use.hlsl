// Large arrays of which only the first elements are read: the table's Size shrinks.
float4 bigArray[64];
float4x4 matArray[8];
float  scalarArray[16];

float4 main(float4 v : TEXCOORD0) : COLOR
{
    return bigArray[2] * v + mul(v, matArray[1]) + scalarArray[5];
}
