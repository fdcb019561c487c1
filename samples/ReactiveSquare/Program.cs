// The paper's reactive loop (Code Sample 7): see ReactiveSquareSample.cs. Any key (or Ctrl+C) stops after the current square.
return await SampleHost.RunAsync(args, Machina.Samples.ReactiveSquareSample.RunAsync, anyKeyStops: true);
