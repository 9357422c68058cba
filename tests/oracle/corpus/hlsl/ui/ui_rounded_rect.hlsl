// Rounded rectangle panel with border computed analytically.
float4 rectSize;        // xy half-size in pixels, z radius, w border
float4 fillColor, borderColor;

float4 main(float2 local : TEXCOORD0) : COLOR
{
    float2 q = abs(local) - rectSize.xy + rectSize.z;
    float dist = length(max(q, 0)) + min(max(q.x, q.y), 0) - rectSize.z;
    float aa = fwidth(dist);
    float outside = saturate(dist / aa + 0.5);
    float border = saturate((dist + rectSize.w) / aa + 0.5);
    float4 c = lerp(fillColor, borderColor, border);
    c.a *= 1 - outside;
    return c;
}
