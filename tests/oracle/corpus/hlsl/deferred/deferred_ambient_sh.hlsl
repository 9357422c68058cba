// Ambient pass: hemisphere term plus an SSAO buffer, writes two targets.
sampler2D normals;
sampler2D albedo;
sampler2D ao;
float3 upVS;
float3 skyCol, groundCol;

void main(float2 uv : TEXCOORD0, out float4 lighting : COLOR0, out float4 debugAO : COLOR1)
{
    float3 n = tex2D(normals, uv).xyz * 2 - 1;
    float occ = tex2D(ao, uv).r;
    float h = dot(n, upVS) * 0.5 + 0.5;
    lighting = float4(tex2D(albedo, uv).rgb * lerp(groundCol, skyCol, h) * occ, 1);
    debugAO = occ.xxxx;
}
