// Classic Phong using reflect() rather than a half vector.
uniform float4 lightPos;
uniform float4 eyePos;
uniform float4 matDiffuse;
uniform float4 matSpecular;   // a = exponent

float4 main(float3 worldPos : TEXCOORD0, float3 worldNrm : TEXCOORD1) : COLOR
{
    float3 N = normalize(worldNrm);
    float3 L = normalize(lightPos.xyz - worldPos);
    float3 V = normalize(eyePos.xyz - worldPos);
    float3 R = reflect(-L, N);
    float d = saturate(dot(N, L));
    float s = pow(saturate(dot(R, V)), matSpecular.a);
    return matDiffuse * d + float4(matSpecular.rgb * s, 0);
}
