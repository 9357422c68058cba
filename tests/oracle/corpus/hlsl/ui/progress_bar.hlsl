// Health bar: fill amount, damage flash, step for the cut.
float fill;
float damageFill;
float4 fullColor, emptyColor, damageColor;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float inFill = step(uv.x, fill);
    float inDamage = step(uv.x, damageFill) * (1 - inFill);
    float4 c = lerp(emptyColor, lerp(emptyColor, fullColor, fill), inFill);
    return lerp(c, damageColor, inDamage);
}
