// Quaternion rotation of a vector (dual-quaternion skinning style helper).
float4 rotationQ;
float3 translation;

float3 QRotate(float4 q, float3 v)
{
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

float4 main(float3 p : TEXCOORD0, float3 n : TEXCOORD1) : COLOR
{
    float3 wp = QRotate(rotationQ, p) + translation;
    float3 wn = QRotate(rotationQ, n);
    return float4(wp * 0.01 + wn, 1);
}
