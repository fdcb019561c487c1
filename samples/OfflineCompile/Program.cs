// Writes the paper's "Hello Robot" program in every language Machina compiles to: see OfflineCompileSample.cs.
return await SampleHost.RunAsync(args, Machina.Samples.OfflineCompileSample.RunAsync);
