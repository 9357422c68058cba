// Vertex colours on COLOR0/COLOR1 (specular add), no textures.
float4 main(float4 diffuse : COLOR0, float4 specular : COLOR1) : COLOR
{
    return float4(diffuse.rgb + specular.rgb, diffuse.a);
}
