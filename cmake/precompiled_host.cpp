// The library objects' header image is made with this empty translation unit (precompiled.cmake).
