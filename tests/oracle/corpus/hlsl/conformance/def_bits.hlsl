// Conformance corpus: literals the compiler writes as `def` values at the bottom of the float
// range: the smallest denormal (1e-45), its negative, and the smallest normal number.
// (Infinite and NaN literals are refused: X4579.)
float4 scale : register(c0);

float4 main() : COLOR
{
    return float4(1e-45, -1e-45, 1.17549435e-38, 0.5) * scale;
}
