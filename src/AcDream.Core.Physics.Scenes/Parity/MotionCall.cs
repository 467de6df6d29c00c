namespace AcDream.Core.Physics.Parity;

/// <summary>One call: what, the motion, speed, hold key, the jump's extent and stamina, and the reference's result ("None" or an error name).</summary>
internal readonly record struct MotionCall(MotionCallKind Kind, uint Motion, float Speed, HoldKey Hold, float Extent, int Stamina, string Expected);
