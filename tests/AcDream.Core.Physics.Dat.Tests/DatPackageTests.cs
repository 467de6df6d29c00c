namespace AcDream.Core.Physics.Dat.Tests;

public class DatPackageTests
{
    [Fact]
    public void TheReferencedReaderIsTheVersionThePackageNames()
    {
        var version = typeof(DatReaderWriter.DatCollection).Assembly.GetName().Version;
        Assert.NotNull(version);
        Assert.Equal(DatPackage.ReaderVersion, $"{version!.Major}.{version.Minor}.{version.Build}");
    }
}
