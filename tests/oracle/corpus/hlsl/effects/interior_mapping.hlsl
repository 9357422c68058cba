// Interior mapping: ray-box intersection in room space, lookup in a cube map of the room.
samplerCUBE roomCube;
float3 roomScale;

float4 main(float3 posOS : TEXCOORD0, float3 viewOS : TEXCOORD1) : COLOR
{
    float3 p = frac(posOS * roomScale) * 2 - 1;
    float3 d = normalize(viewOS);
    float3 id = 1.0 / d;
    float3 k = abs(id) - p * id;
    float t = min(min(k.x, k.y), k.z);
    return texCUBE(roomCube, p + d * t);
}
