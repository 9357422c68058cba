float4 abcdefghijkl;
float4 abcdefghijklm;
float4 main() : COLOR { return abcdefghijkl + abcdefghijklm; }
