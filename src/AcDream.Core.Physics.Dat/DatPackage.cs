namespace AcDream.Core.Physics.Dat;

/// <summary>The DAT adapter's version facts: which DatReaderWriter release it was written and tested against.</summary>
public static class DatPackage
{
    /// <summary>The Chorizite.DatReaderWriter version this package references (2.1.4).</summary>
    public const string ReaderVersion = "2.1.4";
}
