bash tools/demo.sh   # the main job: the oracle, the textbook method's mistakes, a scene, the benchmark
bash tools/test.sh   # the whole test suite (Release, sanitizers, fuzzers, pip install); CI runs both
