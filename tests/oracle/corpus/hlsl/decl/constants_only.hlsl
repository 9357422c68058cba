// The smallest realistic shader: a solid colour from one constant.
float4 Color;
float4 main() : COLOR { return Color; }
