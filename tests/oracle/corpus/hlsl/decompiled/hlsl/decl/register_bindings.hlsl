// ps_3_0 shader decompiled by ps30
float4 Offsets[3] : register(c40);
float4x4 ReflMatrix : register(c20);
float4 Taps : register(c0); // the table's type: int
float4 Tint : register(c10);
bool UseReflect : register(b3);
sampler2D Albedo : register(s3);
samplerCUBE Reflect : register(s7);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = float2(0.0, 1.0);
    r0.y = -Taps.x >= 0.0 ? r0.x : r0.y;
    r1 = -Taps.x >= 0.0 ? r0.x : tex2D(Albedo, (Offsets[0].xy + texcoord0.xy));
    r0.x = r0.y - Taps.x;
    r1 = r0.x >= 0.0 ? r1 : (r1 + tex2D(Albedo, (Offsets[1].xy + texcoord0.xy)));
    r0.y = (r0.x >= 0.0 ? r0.y : 2.0) - Taps.x;
    r2 = r1 + tex2D(Albedo, (Offsets[2].xy + texcoord0.xy));
    r0.y = r0.y >= 0.0 ? -0.0 : -1.0;
    r0 = (r0.x >= 0.0 ? 0.0 : r0.y) >= 0.0 ? r1 : r2;
    r1 = r0 * Tint;
    if (UseReflect) {
        r2.x = dot(texcoord1.xyz, ReflMatrix._m00_m10_m20);
        r2.y = dot(texcoord1.xyz, ReflMatrix._m01_m11_m21);
        r2.z = dot(texcoord1.xyz, ReflMatrix._m02_m12_m22);
        r2 = texCUBE(Reflect, r2.xyz);
        oC0 = r0 * Tint + r2;
    } else {
        oC0 = r1;
    }
    return oC0;
}
